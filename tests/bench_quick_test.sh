#!/bin/sh
# Smoke test of `weft bench --quick`: it runs, writes a CSV with a finite accuracy for every
# opaque GPU method, a PNG chart and a report with the stability table; a second run reads
# the reference from the cache and measures the same errors; bad input exits 2.
set -eu
WEFT="$1"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$WEFT" bench --help >/dev/null || fail "--help"
set +e
"$WEFT" bench --quick --speed-frames 0 --out "$OUT/bad" >/dev/null 2>&1; rc=$?
set -e
[ "$rc" = 2 ] || fail "--speed-frames 0 exited $rc, expected 2"

"$WEFT" bench --quick --out "$OUT/b" > "$OUT/run1.json" || fail "first run"
CSV="$OUT/b/results.csv"
[ -s "$CSV" ] || fail "no CSV"
for m in sgpoint sheen mdfrot; do
  row=$(grep ",$m," "$CSV") || fail "no row for $m"
  rmse=$(echo "$row" | cut -d, -f11)
  ms=$(echo "$row" | cut -d, -f7)
  awk -v e="$rmse" -v t="$ms" 'BEGIN { exit !(e > 0 && e < 100 && t > 0) }' || fail "$m: rmse '$rmse' ms '$ms'"
done
head -c 8 "$OUT/b/chart.png" | od -An -c | grep -q "P   N   G" || fail "chart.png is not a PNG"
grep -q "## Stability" "$OUT/b/report.md" || fail "report has no stability table"
grep -q "0 from the cache" "$OUT/b/report.md" || fail "first run should render its reference"
cut -d, -f1-4,11 "$CSV" > "$OUT/errors1"

"$WEFT" bench --quick --no-stability --out "$OUT/b" > /dev/null || fail "second run"
grep -q "1 from the cache" "$OUT/b/report.md" || fail "second run should read the cached reference"
cut -d, -f1-4,11 "$CSV" > "$OUT/errors2"
cmp -s "$OUT/errors1" "$OUT/errors2" || fail "cached reference gave different errors"
echo "bench --quick: ok"
