#!/bin/bash
# A product file with no cloth in it (assimp-testmodels' glTF 2.0 BoxTextured: one textured box)
# bakes with the weighting tables' sections but no table, and `weft run` shows it with the default
# rung, saying why the knobs do nothing, rather than stopping for want of tables.
set -eu
weft=$1
model=/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf
[ -f "$model" ] || { echo "no $model (apt install assimp-testmodels)"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$weft" bake --scene "$model" --out "$dir/box.weft" 2> "$dir/bake.log"
grep -q "tables for 0 fabric" "$dir/bake.log" || { cat "$dir/bake.log"; echo "the box was baked with cloth"; exit 1; }
"$weft" run --bundle "$dir/box.weft" --state-dir "$dir/state" --display headless --panel none --frames 2 --turntable 0 \
  --width 64 --height 48 --screenshot "$dir/shot.png" 2> "$dir/run.log" || { cat "$dir/run.log"; echo "weft run stopped"; exit 1; }
grep -q "first frame after .* iwasaki_vertex" "$dir/run.log" || { cat "$dir/run.log"; echo "no first frame with the default rung"; exit 1; }
grep -q "the bundle has no cloth" "$dir/run.log" || { cat "$dir/run.log"; echo "no line saying the bundle has no cloth"; exit 1; }
test -s "$dir/shot.png"
