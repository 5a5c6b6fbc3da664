#!/usr/bin/env bash
# Content updates of a running kiosk: bakes two showroom bundles (with the weighting tables, as a
# showroom ships them), starts `weft run` headless on one, then renames the other over it ROUNDS
# times, alternating, as rsync or systemd-sysupdate would. For each update it reports the kiosk's
# own figure (the log line "shown N ms after it changed": from the first inotify event read to the
# end of the first frame of the new scene, with its parts) and the outside one (from the rename
# to that log line appearing, polled every 10 ms).
# Usage: bundle_swap_bench.sh WEFT [ROUNDS=6] [WIDTH=640] [HEIGHT=480]   (label: bench)
set -euo pipefail
WEFT=$1; ROUNDS=${2:-6}; W=${3:-640}; H=${4:-480}
DIR=$(mktemp -d); trap 'kill "$kiosk" 2>/dev/null || true; rm -rf "$DIR"' EXIT
"$WEFT" bake --scene pillow --fabric linen_plain --out "$DIR/a.weft" >"$DIR/bake_a.log" 2>&1
"$WEFT" bake --scene drape --fabric silk_shot --out "$DIR/b.weft" >"$DIR/bake_b.log" 2>&1
echo "bundles: $(du -h "$DIR/a.weft" | cut -f1) pillow/linen_plain, $(du -h "$DIR/b.weft" | cut -f1) drape/silk_shot; ${W}x${H} headless"
cp "$DIR/a.weft" "$DIR/showroom.weft"
"$WEFT" run --bundle "$DIR/showroom.weft" --state-dir "$DIR/state" --display headless --width "$W" --height "$H" \
  --turntable 0 --panel none --frames 0 --stats-every 0 >"$DIR/run.log" 2>&1 &
kiosk=$!
until grep -q "first frame after" "$DIR/run.log"; do kill -0 $kiosk || { cat "$DIR/run.log"; exit 1; }; sleep 0.1; done
grep "first frame after" "$DIR/run.log"
now() { date +%s.%N; }
for ((i = 1; i <= ROUNDS; i++)); do
  src=$DIR/b.weft; [ $((i % 2)) -eq 0 ] && src=$DIR/a.weft
  cp "$src" "$DIR/.incoming" && sync
  t0=$(now)
  mv "$DIR/.incoming" "$DIR/showroom.weft"
  until [ "$(grep -c ' shown ' "$DIR/run.log")" -ge "$i" ]; do
    kill -0 $kiosk || { cat "$DIR/run.log"; exit 1; }
    grep -q "content update refused" "$DIR/run.log" && { cat "$DIR/run.log"; exit 1; }
    sleep 0.01
  done
  t1=$(now)
  line=$(grep ' shown ' "$DIR/run.log" | sed -n "${i}p")
  printf 'update %d: rename -> log line %.0f ms | %s\n' "$i" "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print (b - a) * 1000 }')" "${line#*shown }"
  sleep 1
done
kill -TERM $kiosk; wait $kiosk || true
grep -E "knob state|stopping after" "$DIR/run.log"
