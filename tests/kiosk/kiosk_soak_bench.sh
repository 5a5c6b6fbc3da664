#!/bin/sh
# Soak of the headless kiosk runtime: the simulated panel turns knobs for the whole run,
# the mocked light-probe camera sees the room switch between two maps every 5 s (a lamp going on
# and off; the probe refits 10 SGs live) and the turntable keeps the camera moving; `weft run`
# logs a stats line (frames, median ms/frame, RSS, probe updates) every STATS seconds. Memory and
# frame time should stay flat.
# Usage: kiosk_soak_bench.sh WEFT ASSETS_DIR [SECONDS=180] [STATS=20]   (label: bench)
set -eu
WEFT=$1; ASSETS=$2; SECONDS_TOTAL=${3:-180}; STATS=${4:-20}
DIR=$(mktemp -d); trap 'rm -rf "$DIR"' EXIT
"$WEFT" bake --scene pillow --fabric linen_plain --out "$DIR/pillow.weft" 2>/dev/null
# A hand that keeps turning every dial back and forth, with button clicks, for the whole run.
i=0; : > "$DIR/soak.knobs"
while [ $i -lt $((SECONDS_TOTAL / 4 + 1)) ]; do
  d=$((i % 4))
  printf 'turn %d 6 every 100\nwait 400\nturn %d -6 every 100\nwait 400\nclick %d\nwait 1000\n' $d $d $((i % 5)) >> "$DIR/soak.knobs"
  i=$((i + 1))
done
# SIGTERM after SECONDS: the clean-exit path prints the final line (report->photon, RSS).
timeout -s TERM "$SECONDS_TOTAL" "$WEFT" run --bundle "$DIR/pillow.weft" --state-dir "$DIR/state" --display headless --width 96 --height 72 --turntable 3 \
  --panel "sim:$DIR/soak.knobs" --frames 0 --stats-every "$STATS" \
  --probe "mock:$ASSETS/envmaps/studio.exr,$ASSETS/envmaps/interior.exr" --probe-switch 5 2>&1 |
  grep --line-buffered -E "stats:|stopping|first frame" || true
