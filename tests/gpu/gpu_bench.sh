#!/usr/bin/env bash
# The ladder and the kiosk on a real GPU through EGL (NVIDIA's device platform, headless), at
# 1080p and 4K, and the resolved weave up close: the figures docs/gpu/measured/ holds.
#
#   tests/gpu/gpu_bench.sh BIN_DIR BUNDLE_DIR OUT_DIR [SIZES]
#
# BIN_DIR: weft, weft-offline and kiosk_frame_bench (a build tree's, or copies of them: tests/gpu/gpu_pack.sh).
# BUNDLE_DIR: showroom.weft and pillow.weft, baked with the showroom's grids
#   (weft bake --scene S --table-grid 32 --sdf-resolution 64 --floor-sdf-resolution 32).
# OUT_DIR: gets gpu_bench.log (everything), kiosk_<W>x<H>.md (the kiosk bench's tables),
#   kiosk_check_640x480.md (culled against every vertex, with errors) and
#   showroom_<rung>_<W>x<H>.png (the kiosk's last frame).
# SIZES: "1920x1080 3840x2160" unless given.
# Run from the repository root (assets/). Targets (docs/design.md, speed): the kiosk's default
# rung ≤ 4 ms a frame at 4K. Not in CI: it needs a GPU; on llvmpipe it runs, slowly.
set -uo pipefail
if [ $# -lt 3 ] || [ "${1:-}" = "--help" ]; then sed -n '2,16p' "$0"; exit 2; fi
BIN=$(realpath "$1") BUNDLES=$(realpath "$2") OUT=$3
SIZES=${4:-"1920x1080 3840x2160"}
mkdir -p "$OUT"
OUT=$(realpath "$OUT")
export WEFT_ASSETS=${WEFT_ASSETS:-$PWD/assets}
LOG=$OUT/gpu_bench.log
: >"$LOG"
START=$(date +%s)
say() { echo "$*" | tee -a "$LOG"; }
step() { say "== $* ($(($(date +%s) - START)) s)"; }
# Runs a command with its output in the log; a failing step is reported and the next one runs.
run() { "$@" >>"$LOG" 2>&1 || say "FAILED ($?): $*"; }

step machine
{ nvidia-smi -L 2>/dev/null || echo "no nvidia-smi"; nproc; uname -r
  grep PRETTY_NAME /etc/os-release; } >>"$LOG" 2>&1
for b in showroom pillow; do
  [ -f "$BUNDLES/$b.weft" ] || { say "no $BUNDLES/$b.weft"; exit 1; }
done

# First, whether the driver draws what llvmpipe draws: the kiosk bench turning 2° a frame with
# the per-vertex passes for the visible vertices only against every vertex, error columns on
# (the bench fails where culling changes the frame at R = 1).
# Each case's last frame is counted for cloth pixels that are not finite or black, and each cloth
# object's per-vertex values for the SGs whose values are not (a driver's NaN: black cloth).
step "kiosk culling check 640x480"
shots=$(mktemp -d)
WEFT_KIOSK_BUNDLES="showroom=$BUNDLES/showroom.weft,pillow=$BUNDLES/pillow.weft" WEFT_KIOSK_METHODS=auto,iwasaki_vertex,sheen \
  WEFT_KIOSK_VERTICES=all,visible WEFT_KIOSK_REFRESH=1,b16 WEFT_KIOSK_FRAMES=8 WEFT_KIOSK_DEG_PER_FRAME=2 \
  WEFT_KIOSK_SIZE=640x480 WEFT_KIOSK_SHOTS="$shots" WEFT_KIOSK_OUT="$OUT/kiosk_check_640x480.md" run "$BIN/kiosk_frame_bench"
grep -q -E "[1-9][0-9]* not finite|vertices not finite" "$LOG" && say "NOT FINITE: the driver drew NaN cloth (census lines in the log)"
rm -rf "$shots"

# The kiosk's frame, the way `weft run` draws it, turning 0.4° a frame: stages by GPU timestamps.
for size in $SIZES; do
  step "kiosk bench $size"
  WEFT_KIOSK_BUNDLES="showroom=$BUNDLES/showroom.weft,pillow=$BUNDLES/pillow.weft" \
    WEFT_KIOSK_METHODS=auto,iwasaki_vertex,sheen WEFT_KIOSK_REFRESH=1,b16 WEFT_KIOSK_FRAMES=60 \
    WEFT_KIOSK_SIZE="$size" WEFT_KIOSK_NO_ERROR=1 WEFT_KIOSK_OUT="$OUT/kiosk_$size.md" \
    run "$BIN/kiosk_frame_bench"
  # The zoom: the weave layer lit per pixel (on), from its per-vertex table, and off.
  step "kiosk zoom $size"
  WEFT_KIOSK_BUNDLES="showroom=$BUNDLES/showroom.weft" WEFT_KIOSK_METHODS=auto WEFT_KIOSK_REFRESH=4 \
    WEFT_KIOSK_ZOOMS=0,0.5,1 WEFT_KIOSK_WEAVE=on,table,off WEFT_KIOSK_FRAMES=30 \
    WEFT_KIOSK_SIZE="$size" WEFT_KIOSK_NO_ERROR=1 WEFT_KIOSK_OUT="$OUT/kiosk_zoom_$size.md" \
    run "$BIN/kiosk_frame_bench"
done

# The kiosk itself, headless, its default rung and settings, a GPU frame profile in its stats.
# `iwasaki_vertex` at the first size too: a frame to compare with the default rung's.
for run_case in $(for size in $SIZES; do echo "auto:$size"; done) "iwasaki_vertex:${SIZES%% *}"; do
  method=${run_case%%:*} size=${run_case#*:}
  step "weft run showroom $method $size"
  w=${size%x*} h=${size#*x}
  state=$(mktemp -d)
  run "$BIN/weft" run --bundle "$BUNDLES/showroom.weft" --state-dir "$state" --display headless --panel none --method "$method" \
    --width "$w" --height "$h" --frames 300 --stats-every 2 --profile gpu --screenshot "$OUT/showroom_${method}_$size.png"
  rm -rf "$state"
done

# The ladder: each rung on the pillow (and the showroom's armchair), one frame's median.
for size in $SIZES; do
  w=${size%x*} h=${size#*x}
  for bundle in pillow showroom; do
    step "ladder $bundle $size"
    for m in sheen iwasaki_vertex mdfrot sgpoint iwasaki; do
      # The rungs without tables read the scene file; the slow ones (hundreds of ms a frame) time fewer.
      source=(--scene "$bundle") frames=10
      case $m in iwasaki_vertex | iwasaki) source=(--bundle "$BUNDLES/$bundle.weft") ;; esac
      case $m in sheen | iwasaki_vertex) frames=60 ;; sgpoint | iwasaki) frames=4 ;; esac
      say "$bundle $m $size: $("$BIN/weft" render "${source[@]}" --method "$m" --width "$w" --height "$h" \
        --frames $frames --out /tmp/gpu_bench_frame.exr 2>>"$LOG" | tail -1)"
    done
  done
done

# The resolved weave up close (the scene's close-up camera) against the fabric level, same view.
for size in 640x480 $SIZES; do
  w=${size%x*} h=${size#*x}
  step "weave close-up $size"
  for weave in "" --weave "--weave --weave-terms table"; do
    say "pillow iwasaki_vertex closeup ${weave:-fabric-level} $size: $("$BIN/weft" render --bundle "$BUNDLES/pillow.weft" \
      --method iwasaki_vertex --camera closeup $weave --width "$w" --height "$h" --frames 60 \
      --out /tmp/gpu_bench_frame.exr 2>>"$LOG" | tail -1)"
  done
done
step done
