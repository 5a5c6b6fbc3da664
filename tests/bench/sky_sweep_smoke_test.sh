#!/bin/sh
# Smoke test of `weft bench --sweep sky-smoke`: the swatch under a sun on the horizon, a larger
# sun at 20° and a turned bundled map; low_sun.csv has a finite iwasaki, iwasaki_vertex,
# iwasaki_vertex_mask, iwasaki_mask, iwasaki_vertex_quadrature, iwasaki_quadrature, iwasaki_vertex_mask_quadrature
# and iwasaki_mask_quadrature error per environment, the fit's irradiance error within
# the 3 % bound and the reference's fixed 8 tangent samples; bad specs exit 2.
set -eu
WEFT="$1"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

expect_usage_error() {
  set +e
  "$WEFT" bench "$@" --out "$OUT/bad" >"$OUT/bad.log" 2>&1; rc=$?
  set -e
  [ "$rc" = 2 ] || fail "$* exited $rc, expected 2"
}
expect_usage_error --sweep bogus
expect_usage_error --sweep sky-smoke --maps sky:elev=95
expect_usage_error --sweep sky-smoke --maps sky:elev=5,colour=3
grep -q "unknown sky parameter 'colour'" "$OUT/bad.log" || fail "message should name the unknown key"
expect_usage_error --sweep sky-smoke --maps nosuchmap@90

"$WEFT" bench --sweep sky-smoke --out "$OUT/s" >/dev/null || fail "sweep run"
CSV="$OUT/s/low_sun.csv"
[ -s "$CSV" ] || fail "no low_sun.csv"
[ "$(tail -n +2 "$CSV" | wc -l)" = 3 ] || fail "expected 3 cases in low_sun.csv"
grep -q '^swatch,linen_plain,"sky:elev=20,size=2",' "$CSV" || fail "the sky spec should be one quoted CSV field"
grep -q '^swatch,linen_plain,studio@90,' "$CSV" || fail "no row for studio@90"
# Fields after the quoted env: strip it first.
sed 's/"[^"]*"/ENV/' "$CSV" | tail -n +2 | while IFS=, read -r scene fabric env iw vx fit probe ms nj mk pm vq pq vmq pmq; do
  awk -v a="$iw" -v b="$vx" -v f="$fit" -v p="$probe" -v t="$ms" -v m="$mk" -v q="$pm" -v r="$vq" -v s="$pq" -v u="$vmq" -v w="$pmq" \
    'BEGIN { exit !(a > 0 && a < 1 && b > 0 && b < 1 && f >= 0 && f <= 0.03 && p >= 0 && p < 0.1 && t > 0 && m > 0 && m < 1 && q > 0 && q < 1 && r > 0 && r < 1 && s > 0 && s < 1 && u > 0 && u < 1 && w > 0 && w < 1) }' ||
    fail "$env: iwasaki $iw, vertex $vx, fit $fit, probe $probe, $ms ms, vertex mask $mk, pixel mask $pm, vertex quadrature $vq, pixel quadrature $pq, vertex mask quadrature $vmq, pixel mask quadrature $pmq"
  [ "$nj" = 8 ] || fail "$env: the smoke sweep's reference keeps 8 tangent samples, got '$nj'"
done
grep -q "^Summary: iwasaki worst" "$OUT/s/low_sun.md" || fail "low_sun.md has no summary"
grep -q "sky:elev=0" "$OUT/s/results.csv" || fail "results.csv has no sky row"
echo "bench --sweep sky-smoke: ok"
