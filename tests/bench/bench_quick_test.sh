#!/bin/sh
# Smoke test of `weft bench --quick`: it runs, writes a CSV with a finite accuracy for every
# opaque GPU method (iwasaki's `--target-error` row included), a PNG chart, the knob sweeps and
# a report with the stability table (3 timed frames a rung: the smoke checks times exist, the
# bench proper measures them); a second run (no sweeps, no stability table) reads the reference
# from the cache and measures the same errors, every method included; bad input exits 2.
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
set +e
"$WEFT" bench --quick --sweep-svd-error 0 --out "$OUT/bad" >/dev/null 2>&1; rc=$?
set -e
[ "$rc" = 2 ] || fail "--sweep-svd-error 0 exited $rc, expected 2"
set +e
"$WEFT" bench --quick --no-sweeps --sweep-svd-error 0.1 --out "$OUT/bad" >/dev/null 2>&1; rc=$?
set -e
[ "$rc" = 2 ] || fail "--no-sweeps with a sweep exited $rc, expected 2"

"$WEFT" bench --quick --speed-frames 3 --out "$OUT/b" > "$OUT/run1.json" || fail "first run"
CSV="$OUT/b/results.csv"
[ -s "$CSV" ] || fail "no CSV"
for m in sgpoint sheen mdfrot iwasaki "iwasaki (target 0.05)"; do
  row=$(grep ",$m," "$CSV") || fail "no row for $m"
  rmse=$(echo "$row" | cut -d, -f11)
  ms=$(echo "$row" | cut -d, -f7)
  awk -v e="$rmse" -v t="$ms" 'BEGIN { exit !(e > 0 && e < 100 && t > 0) }' || fail "$m: rmse '$rmse' ms '$ms'"
done
grep -q "against the paper's settings" "$OUT/b/report.md" || fail "report has no target-error table"
# The target rows name their setting (per-vertex: with the cloth mesh's subdivision), the SGs
# they were lit by and the subdivision chosen, in the CSV's last columns; the last is the
# reference's tangent samples, --quick's fixed 8.
grep ",iwasaki_vertex (target 0.05)," "$CSV" | grep -Eq '"iwasaki_vertex, [0-9]+\+[0-9]+ samples per curved thread, .*subdivision [0-2]",10,[0-2],[0-9]+,,8$' ||
  fail "iwasaki_vertex target row: no setting, SG count or subdivision"
grep ",iwasaki (target 0.05)," "$CSV" | grep -Eq '"iwasaki, [0-9]+\+[0-9]+ samples per curved thread, [^"]*",10,0,[0-9]+,,8$' ||
  fail "iwasaki target row: no setting, SG count or subdivision"
# Knob sweeps (swatch: linen_plain, whose paper setting is 3+3 tangent samples, SVD error 0.01).
# The point equal to the paper default is the main iwasaki row's bake: the same error.
iw=$(grep ",iwasaki," "$CSV" | cut -d, -f11)
value() { grep "^$2,$3," "$OUT/b/$1" | cut -d, -f"$4"; }
TS=sweep_tangent_samples.csv SV=sweep_svd_error.csv
[ "$(value $TS "tangent samples per thread" 3 4)" = "$iw" ] || fail "tangent samples 3 should reproduce iwasaki's $iw"
[ "$(value $SV "SVD error" 0.01 4)" = "$iw" ] || fail "SVD error 0.01 should reproduce iwasaki's $iw"
# One sample per thread misses most of the yarn's curve; a looser SVD target keeps fewer ranks.
awk -v a="$(value $TS "tangent samples per thread" 1 4)" -v b="$iw" 'BEGIN { exit !(a > b) }' ||
  fail "1 tangent sample should be worse than 3"
awk -v a="$(value $SV "SVD error" 0.1 5)" -v b="$(value $SV "SVD error" 0.01 5)" 'BEGIN { exit !(a < b) }' ||
  fail "SVD error 0.1 should store fewer table bytes than 0.01"
grep -q "## Cost knob: iwasaki SVD error" "$OUT/b/report.md" || fail "report has no SVD sweep"
for m in iwasaki mizutani; do
  sed -n '/^## Stability/,$p' "$OUT/b/report.md" | grep -q "^| $m | [0-9]" || fail "stability table has no $m row"
done
head -c 8 "$OUT/b/chart.png" | od -An -c | grep -q "P   N   G" || fail "chart.png is not a PNG"
grep -q "## Stability" "$OUT/b/report.md" || fail "report has no stability table"
grep -q "0 from the cache" "$OUT/b/report.md" || fail "first run should render its reference"
grep -q ",iwasaki_vertex," "$CSV" || fail "no row for iwasaki_vertex"
cut -d, -f1-4,11 "$CSV" > "$OUT/errors1"

"$WEFT" bench --quick --speed-frames 1 --no-stability --no-sweeps --out "$OUT/b" > /dev/null || fail "second run"
grep -q "1 from the cache" "$OUT/b/report.md" || fail "second run should read the cached reference"
cut -d, -f1-4,11 "$CSV" > "$OUT/errors2"
cmp -s "$OUT/errors1" "$OUT/errors2" || fail "cached reference gave different errors"
echo "bench --quick: ok"
