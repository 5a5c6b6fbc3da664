#!/usr/bin/env bash
# The kiosk unit passes `systemd-analyze verify` and its offline security exposure is <= 2.0.
# Usage: systemd_unit_test.sh UNIT_TEMPLATE WEFT_BINARY
set -euo pipefail
template=$1 binary=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# verify wants ExecStart to exist: point it at the build's binary.
sed "s|@WEFT_BINDIR@/weft|$binary|" "$template" > "$dir/weft.service"
systemd-analyze verify "$dir/weft.service"
report=$(systemd-analyze security --offline=true "$dir/weft.service" 2>&1)
line=$(grep "Overall exposure level" <<<"$report")
echo "$line"
score=$(sed -E 's/.*: ([0-9.]+) .*/\1/' <<<"$line")
awk -v s="$score" 'BEGIN { exit !(s <= 2.0) }' || { echo "exposure $score is above 2.0"; exit 1; }
