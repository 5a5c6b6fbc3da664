#!/bin/sh
# The catalogue's costs on a product file: a glTF as a product tool writes it
# (tests/scene/make_product_gltf.py: a cushion with a baseColorTexture under KHR_texture_transform
# and two KHR_materials_variants colourways), and the same file without its texture and without
# its variants, baked alike. Reports
#   - bundle bytes: the texture sections, and what the texture and the second colourway add;
#   - the kiosk's median frame on the turntable with and without the texture;
#   - change → photon with the turntable still, while a simulated panel presses the colourway
#     button, turns the hue dial or the gloss dial every 1.5 s: the kiosk's own measure (report
#     arrival → end of the first frame showing it), also in frames of its median frame time.
# Usage: catalogue_bench.sh WEFT SCENE_TOOLS_DIR [WIDTH=640] [HEIGHT=480] [PRESSES=12]   (label: bench)
# WEFT_CATALOGUE_BAKE: the bake's grid options (the smoke takes the coarsest, seconds of CPU).
set -eu
WEFT=$1; TOOLS=$2; WIDTH=${3:-640}; HEIGHT=${4:-480}; PRESSES=${5:-12}
BAKE=${WEFT_CATALOGUE_BAKE:---table-grid 16 --sdf-resolution 32 --floor-sdf-resolution 16}
DIR=$(mktemp -d); trap 'rm -rf "$DIR"' EXIT
python3 "$TOOLS/make_product_gltf.py" "$DIR" >/dev/null
# A texture the size a product tool exports (512², a yarn-dyed check with per-texel yarn noise,
# so that it compresses as a photographed fabric does) in place of the generator's tiny one.
python3 - "$DIR/cushion_weave.png" <<'PY'
import random, struct, sys, zlib
n, rng, rows = 512, random.Random(7), b""
for y in range(n):
    row = bytearray([0])
    for x in range(n):
        band = ((x // 48) + (y // 48)) % 3
        base = ((200, 60, 50), (40, 70, 150), (230, 220, 200))[band]
        j = rng.randint(-18, 18)
        row += bytes(max(0, min(255, c + j)) for c in base)
    rows += bytes(row)
chunk = lambda k, d: struct.pack(">I", len(d)) + k + d + struct.pack(">I", zlib.crc32(k + d) & 0xFFFFFFFF)
open(sys.argv[1], "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", n, n, 8, 2, 0, 0, 0))
                              + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
PY
# The variants: without the texture (both materials keep their factors), without the colourways.
python3 - "$DIR" <<'PY'
import json, sys
d = sys.argv[1]
g = json.load(open(f"{d}/cushion.gltf"))
plain = json.loads(json.dumps(g))
for m in plain["materials"]:
    m["pbrMetallicRoughness"].pop("baseColorTexture", None)
for k in ("textures", "images", "samplers"):
    plain.pop(k, None)
json.dump(plain, open(f"{d}/plain.gltf", "w"))
one = json.loads(json.dumps(g))
one.pop("extensions", None)
one["extensionsUsed"] = [e for e in one.get("extensionsUsed", []) if e != "KHR_materials_variants"]
for mesh in one["meshes"]:
    for p in mesh["primitives"]:
        p.pop("extensions", None)
json.dump(one, open(f"{d}/one.gltf", "w"))
PY
for b in cushion plain one; do
  # shellcheck disable=SC2086  # BAKE is a list of options
  "$WEFT" bake --scene "$DIR/$b.gltf" $BAKE --out "$DIR/$b.weft" >"$DIR/bake-$b.log" 2>&1 || { cat "$DIR/bake-$b.log" >&2; exit 1; }
done
echo '{"colourway_button": 3}' > "$DIR/panel.json"

size() { stat -c %s "$1"; }
textures=$("$WEFT" bundle info --json "$DIR/cushion.weft" | python3 -c '
import json, sys
info = json.load(sys.stdin)
print(sum(s["bytes"] for s in info["sections"] if s["name"].startswith("texture/")))')

echo "Machine: $(uname -m), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); ${WIDTH}×${HEIGHT} headless"
echo
echo "| bundle | bytes |"
echo "|---|---|"
echo "| textured, two colourways | $(size "$DIR/cushion.weft") |"
echo "| its texture section (a 512² yarn-dyed check, $(size "$DIR/cushion_weave.png") bytes as a PNG file) | $textures |"
echo "| without the texture | $(size "$DIR/plain.weft") ($(( $(size "$DIR/cushion.weft") - $(size "$DIR/plain.weft") )) for the texture) |"
echo "| without the second colourway | $(size "$DIR/one.weft") ($(( $(size "$DIR/cushion.weft") - $(size "$DIR/one.weft") )) for the colourway) |"
echo

# The turntable's median frame (6°/s, a frame every tick) over 40 frames.
frame_ms() {
  "$WEFT" run --bundle "$DIR/$1.weft" --state-dir "$DIR/state-frame-$1" --display headless --width "$WIDTH" \
    --height "$HEIGHT" --turntable 6 --probe none --panel none --frames 40 2>&1 |
    sed -n 's/.*stopping after.*median \([0-9.]*\) ms\/frame.*/\1/p'
}
with=$(frame_ms cushion); without=$(frame_ms plain)
[ -n "$with" ] && [ -n "$without" ] || { echo "no frame statistics from weft run" >&2; exit 1; }
awk -v a="$with" -v b="$without" 'BEGIN {
  printf "| turntable frame | median ms |\n|---|---|\n| with the texture | %.1f |\n| without | %.1f |\n| ratio | %.2f× |\n\n", a, b, a / b }'

# One run: ACTION is a knob-script line repeated PRESSES times, 1.5 s apart.
measure() {
  name=$1; action=$2
  printf 'wait 2000\n' > "$DIR/$name.knobs"
  i=0
  while [ $i -lt "$PRESSES" ]; do
    printf '%s\nwait 1500\n' "$action" >> "$DIR/$name.knobs"
    i=$((i + 1))
  done
  seconds=$((3 + PRESSES * 3 / 2 + 2))
  line=$(timeout -s TERM "$seconds" "$WEFT" run --bundle "$DIR/cushion.weft" --state-dir "$DIR/state-$name" \
    --display headless --width "$WIDTH" --height "$HEIGHT" --turntable 0 --probe none --frames 0 \
    --panel "sim:$DIR/$name.knobs" --panel-config "$DIR/panel.json" 2>&1 | grep "stopping after" || true)
  frame=$(echo "$line" | sed -n 's/.*median \([0-9.]*\) ms\/frame.*/\1/p')
  shown=$(echo "$line" | sed -n 's/.* \([0-9]*\) knob changes shown.*/\1/p')
  median=$(echo "$line" | sed -n 's/.*report->photon median \([0-9.]*\) ms max \([0-9.]*\) ms.*/\1/p')
  worst=$(echo "$line" | sed -n 's/.*report->photon median \([0-9.]*\) ms max \([0-9.]*\) ms.*/\2/p')
  if [ -z "$median" ] || [ -z "$frame" ] || [ "${shown:-0}" -eq 0 ]; then
    echo "$name: the kiosk showed no change (its last line: ${line:-none})" >&2
    exit 1
  fi
  awk -v n="$name" -v f="$frame" -v s="$shown" -v m="$median" -v w="$worst" 'BEGIN {
    printf "| %s | %s | %.1f | %.1f (%.2f frames) | %.1f (%.2f frames) |\n", n, s, f, m, m / f, w, w / f }'
}

echo "| change | changes shown | ms/frame (median) | report → photon median ms | worst ms |"
echo "|---|---|---|---|---|"
measure colourway "click 3"
measure hue "turn 0 4"
measure gloss "turn 2 4"
