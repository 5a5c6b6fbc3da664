#!/bin/bash
# `weft bake` with the weighting tables (small grids), then `weft run` picks iwasaki_vertex_quadrature
# from the bundle (auto: the bake's default masks cover the occluded pillow), iwasaki_vertex from a
# bundle baked --no-masks, the rung `weft bake --choose-rung` measured closer, or iwasaki (asked) and
# shows a first frame, and `weft render --method iwasaki --bundle` writes an image.
set -eu
weft=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$weft" bake --scene pillow --fabric linen_plain --table-grid 8 --tangent-samples 1 1 --sdf-resolution 8 --out "$dir/p.weft" 2> "$dir/bake.log"
grep -q "PCA" "$dir/bake.log" || { cat "$dir/bake.log"; echo "no visibility baked for the pillow"; exit 1; }
grep -q "bundle .* MB" "$dir/bake.log" || { cat "$dir/bake.log"; exit 1; }
"$weft" run --bundle "$dir/p.weft" --state-dir "$dir/state" --display headless --panel none --frames 2 --turntable 0 \
  --width 48 --height 36 --screenshot "$dir/shot.png" 2> "$dir/run.log"
grep -q "first frame after .* iwasaki_vertex_quadrature;" "$dir/run.log" || { cat "$dir/run.log"; echo "weft run did not use iwasaki_vertex_quadrature"; exit 1; }
test -s "$dir/shot.png"
grep -q "visibility mask" "$dir/bake.log" || { cat "$dir/bake.log"; echo "the default bake wrote no visibility mask"; exit 1; }
"$weft" bake --scene pillow --fabric linen_plain --table-grid 8 --tangent-samples 1 1 --sdf-resolution 8 --no-masks --out "$dir/n.weft" 2> "$dir/bake_n.log"
! grep -q "visibility mask" "$dir/bake_n.log" || { cat "$dir/bake_n.log"; echo "--no-masks baked a mask"; exit 1; }
[ "$(stat -c %s "$dir/n.weft")" -lt "$(stat -c %s "$dir/p.weft")" ] || { echo "--no-masks: the bundle is not smaller"; exit 1; }
"$weft" run --bundle "$dir/n.weft" --state-dir "$dir/state_n" --display headless --panel none --frames 2 --turntable 0 \
  --width 48 --height 36 2> "$dir/run_n.log"
grep -q "first frame after .* iwasaki_vertex;" "$dir/run_n.log" || { cat "$dir/run_n.log"; echo "weft run on a --no-masks bundle did not use iwasaki_vertex"; exit 1; }
"$weft" run --bundle "$dir/p.weft" --state-dir "$dir/state" --display headless --panel none --frames 2 --turntable 0 \
  --width 48 --height 36 --method iwasaki 2> "$dir/run_pixel.log"
grep -q "first frame after .* iwasaki;" "$dir/run_pixel.log" || { cat "$dir/run_pixel.log"; echo "weft run --method iwasaki did not use it"; exit 1; }
"$weft" render --method iwasaki --bundle "$dir/p.weft" --width 48 --height 36 --frames 1 --out "$dir/f.exr" > "$dir/render.json"
grep -q '"method":"iwasaki"' "$dir/render.json"
test -s "$dir/f.exr"
# --choose-rung measures the SDF's and the masks' per-vertex rung on the pillow's views (tiny here) and
# weft run --method auto draws the one it recorded; on the unoccluded swatch there is nothing to choose.
"$weft" bake --scene pillow --fabric linen_plain --table-grid 8 --tangent-samples 1 1 --sdf-resolution 8 --choose-rung --choose-width 24 --choose-height 18 \
  --reference-cache "$dir/refs" --out "$dir/c.weft" 2> "$dir/bake_c.log"
chosen=$(sed -n 's/.*; rung \(iwasaki_vertex[a-z_]*_quadrature\) (.*/\1/p' "$dir/bake_c.log")
[ -n "$chosen" ] || { cat "$dir/bake_c.log"; echo "--choose-rung chose no rung"; exit 1; }
grep -q "iwasaki_vertex_mask_quadrature: error 0\." "$dir/bake_c.log" || { cat "$dir/bake_c.log"; echo "--choose-rung did not measure the masks' rung"; exit 1; }
"$weft" run --bundle "$dir/c.weft" --state-dir "$dir/state_c" --display headless --panel none --frames 2 --turntable 0 \
  --width 48 --height 36 2> "$dir/run_c.log"
grep -q "first frame after .* $chosen;" "$dir/run_c.log" || { cat "$dir/run_c.log"; echo "weft run did not draw the chosen $chosen"; exit 1; }
"$weft" bake --scene swatch --table-grid 8 --tangent-samples 1 1 --choose-rung --choose-width 24 --choose-height 18 --reference-cache "$dir/refs" \
  --out "$dir/sw.weft" 2> "$dir/bake_sw.log"
grep -q "no occluded cloth: no rung to choose" "$dir/bake_sw.log" || { cat "$dir/bake_sw.log"; exit 1; }
set +e
"$weft" bake --scene pillow --choose-rung --no-masks --out "$dir/x.weft" 2> /dev/null
rc=$?
set -e
[ $rc -eq 2 ] || { echo "--choose-rung --no-masks: expected exit 2, got $rc"; exit 1; }
# A bundle without tables runs sgpoint; asking it for iwasaki is bad input (exit 2).
"$weft" bake --scene swatch --no-tables --out "$dir/s.weft" 2> /dev/null
set +e
"$weft" run --bundle "$dir/s.weft" --state-dir "$dir/state2" --display headless --panel none --frames 1 --method iwasaki \
  --width 16 --height 12 2> "$dir/run2.log"
rc=$?
set -e
[ $rc -eq 2 ] || { cat "$dir/run2.log"; echo "expected exit 2, got $rc"; exit 1; }
grep -q "no weighting tables" "$dir/run2.log"
echo ok
