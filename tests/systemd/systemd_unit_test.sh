#!/usr/bin/env bash
# The kiosk unit passes `systemd-analyze verify`, its offline security exposure is <= 2.0, it
# waits for the display's device rather than the deprecated systemd-udev-settle, and it reads the
# operator's /etc/weft/weft.conf into the command line.
# Usage: systemd_unit_test.sh UNIT_TEMPLATE WEFT_BINARY
set -euo pipefail
template=$1 binary=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# verify wants ExecStart to exist: point it at the build's binary.
sed -e "s|@WEFT_BINDIR@/weft|$binary|" -e "s|@WEFT_CONFDIR@|/etc/weft|" "$template" > "$dir/weft.service"
systemd-analyze verify "$dir/weft.service"
report=$(systemd-analyze security --offline=true "$dir/weft.service" 2>&1)
line=$(grep "Overall exposure level" <<<"$report")
echo "$line"
score=$(sed -E 's/.*: ([0-9.]+) .*/\1/' <<<"$line")
awk -v s="$score" 'BEGIN { exit !(s <= 2.0) }' || { echo "exposure $score is above 2.0"; exit 1; }

# A setting's values, all its lines joined (comment lines start with '#' and never match).
value() { sed -n "s/^$1=//p" "$dir/weft.service" | tr '\n' ' '; }
fail() { echo "weft.service: $*"; exit 1; }
for key in After Wants Requires BindsTo; do
  ! grep -q "udev-settle" <<<"$(value "$key")" || fail "$key= names systemd-udev-settle.service (deprecated)"
done
grep -qw "dev-dri-card0.device" <<<"$(value After)" || fail "After= does not wait for the display (dev-dri-card0.device)"
grep -qw "dev-dri-card0.device" <<<"$(value Wants)" || fail "Wants= does not pull in the display (dev-dri-card0.device)"
[ "$(value EnvironmentFile)" = "-/etc/weft/weft.conf " ] || fail "EnvironmentFile= is '$(value EnvironmentFile)', not -/etc/weft/weft.conf"
for var in WEFT_BUNDLE WEFT_PANEL_CONFIG WEFT_PROBE WEFT_EXPOSURE WEFT_EXPOSURE_BIAS WEFT_LABEL WEFT_LABEL_POSITION WEFT_LABEL_SIZE WEFT_LABEL_IDLE WEFT_IDLE_RETURN WEFT_SCREEN_OFF WEFT_CONNECTOR WEFT_MODE WEFT_ROTATION WEFT_DISPLAY_WAIT WEFT_RUN_FLAGS; do
  grep -q "$var" <<<"$(value ExecStart)" || fail "ExecStart= does not use $var"
  grep -q "$var=" <<<"$(value Environment)" || fail "Environment= has no default for $var"
done
echo "no udev-settle; waits for dev-dri-card0.device; reads /etc/weft/weft.conf"
