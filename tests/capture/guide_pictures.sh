#!/usr/bin/env bash
# The content guide's pictures of a fabric fitted from photographs (docs/content-guide.md, "A fabric
# from photographs"): the card, a photo, the fit's side-by-side, the fitted fabric on the pillow
# beside the fabric the photos were simulated from, and a close-up (shot silk's two threads).
# The photos are simulated (`weft capture --simulate`), since this machine has no camera.
#   tests/capture/guide_pictures.sh [BUILD_DIR]      # writes docs/capture/*.png
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
weft="${1:-$root/build}/render/app/weft"
out="$root/docs/capture"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
export WEFT_ASSETS="$root/assets"

echo "1/6 the card"
"$weft" capture --card "$out/card.png" --dpi 50

echo "2/6 four photos of linen_plain under the interior map"
"$weft" capture --simulate linen_plain --map interior --out "$work/shots" --photos 4 --seed 3 --width 800 --height 600
cp "$work/shots/photo_01.jpg" "$out/photo.jpg"

echo "3/6 the fit"
"$weft" capture "$work/shots" --out "$work/fitted.json" --report "$out/side_by_side.png" --truth linen_plain --check-map courtyard
cp "$work/fitted.json" "$out/fitted_linen.json"

echo "4/6 the pillow in the fabric the photos were simulated from"
"$weft" render --scene pillow --fabric linen_plain --method iwasaki_vertex --width 400 --frames 1 --out "$work/truth.exr" | tee "$work/truth.json"
cp "$work/truth.png" "$out/pillow_truth.png"
exposure="$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["png_exposure"])' "$work/truth.json")"

echo "5/6 the pillow in the fitted fabric, at the same exposure"
"$weft" render --scene pillow --fabric "$work/fitted.json" --method iwasaki_vertex --width 400 --frames 1 --exposure "$exposure" --out "$work/fitted.exr"
cp "$work/fitted.png" "$out/pillow_fitted.png"

echo "6/6 a close-up of shot silk (its green warp and red weft resolved)"
"$weft" capture --simulate silk_shot --map interior --out "$work/silk" --photos 3 --seed 3 --width 640 --height 480
cp "$work/silk/closeup.jpg" "$out/closeup_silk_shot.jpg"
echo "wrote $(ls "$out" | tr '\n' ' ')"
