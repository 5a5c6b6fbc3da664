#!/bin/bash
# The guest half of tests/kiosk/kiosk_vm_test.sh: runs in the VM as root, chrooted into the host's
# root (read-only over 9p), with OUT (this run's output folder) writable. Talks to the host
# through files in OUT: it touches at-<step> when a step is done and waits for go-<step>
# (the host takes its screendump in between). Everything it learns goes to OUT/*.log.
set -u
OUT=$1
. "$OUT/guest.env"  # WEFT SIM (the package's) UHID_TEST BUNDLE PANEL_CONFIG TURN1 TURN2 WAIT_S
export HOME=/run TMPDIR=/run XDG_RUNTIME_DIR=/run  # /tmp is the host's, read-only
up() { cut -d' ' -f1 /proc/uptime; }
mark() {
  echo "$(up) $1" >>"$OUT/marks"
  touch "$OUT/at-$1"
}
die() {
  echo "guest: $*" | tee -a "$OUT/guest.log"
  mark failed
  exit 1
}
wait_for_file() {  # PATH SECONDS
  local i
  for ((i = 0; i < $2 * 10; i++)); do
    [ -e "$1" ] && return 0
    sleep 0.1
  done
  return 1
}
wait_go() { wait_for_file "$OUT/go-$1" "$WAIT_S" || die "the host never said go-$1"; }
wait_log() {  # PATTERN SECONDS: until the kiosk's log has it (or the kiosk died)
  local i
  for ((i = 0; i < $2 * 10; i++)); do
    grep -q -- "$1" "$OUT/kiosk.log" && return 0
    kill -0 "$kiosk" 2>/dev/null || die "the kiosk exited while waiting for '$1'"
    sleep 0.1
  done
  die "no '$1' in the kiosk's log after $2 s"
}
# The kiosk is idle once two stats lines in a row, both logged after `since` stats lines,
# count the same frames drawn: no knob change left to show.
wait_idle() {  # SINCE SECONDS
  local i lines
  local -a counts
  for ((i = 0; i < $2 * 10; i++)); do
    counts=($(grep -o 'stats: [0-9]* ticks, [0-9]* frames' "$OUT/kiosk.log" | awk '{print $4}'))
    lines=${#counts[@]}
    if ((lines >= $1 + 2)) && [ "${counts[lines - 1]}" = "${counts[lines - 2]}" ]; then return 0; fi
    kill -0 "$kiosk" 2>/dev/null || die "the kiosk exited while it should be drawing"
    sleep 0.5
  done
  die "the kiosk did not settle within $2 s"
}
stats_lines() { grep -c 'stats: ' "$OUT/kiosk.log"; }

echo "guest: $(uname -r), $(nproc) CPUs, steps start at $(up) s" >"$OUT/guest.log"
# The programs are the package's: dpkg-deb -x laid them over the root (guest_init.sh); the host's
# own root has no /usr/bin/weft.
[ -x "$WEFT" ] && [ -x "$SIM" ] || die "the package's $WEFT or $SIM is missing"
echo "weft: $WEFT from the package ($(stat -c %s "$WEFT") bytes), helpers: $(ls /usr/libexec/weft | tr '\n' ' ')" >>"$OUT/guest.log"
mark userspace

# Only the kiosk's package is installed: the offline commands (weft-tools) and the camera probe's
# plugin (weft-probe-camera) are not, and weft says which package to install.
"$WEFT" eval --fabric linen_plain --view 0.5,0.2,0.8 --sg -0.3,0.1,0.9,20,1,1,1 >"$OUT/eval.json" 2>"$OUT/eval.log"
echo "eval exit $?" >>"$OUT/eval.log"
"$WEFT" probe --frames 1 >"$OUT/probe.log" 2>&1
echo "probe exit $?" >>"$OUT/probe.log"

# The uhid panel against the real kernel and hidapi, as a unit test (skips outside such a VM).
"$UHID_TEST" --gtest_filter='UhidPanel.RealUhid*' >"$OUT/uhid_test.log" 2>&1
echo $? >"$OUT/uhid_test.rc"

# The kiosk on the real display: /dev/dri/card0 is bochs; the panel comes through hidraw.
"$WEFT" run --bundle "$BUNDLE" --state-dir "$OUT/state" --display kms --panel hid \
  --panel-config "$PANEL_CONFIG" --turntable 0 --stats-every 2 >"$OUT/kiosk.log" 2>&1 &
kiosk=$!
wait_log "first frame after" "$WAIT_S"
wait_log "listening to USB knob panel" 30
mark first-frame
wait_go before-shot

# Plug the panel in (uhid), turn a knob, unplug it (the simulator destroys the device at exit).
"$SIM" --uhid --panel-config "$PANEL_CONFIG" --hold-ms 1000 "$TURN1" >"$OUT/sim1.log" 2>&1 ||
  die "the panel simulator failed (first plug): $(tail -1 "$OUT/sim1.log")"
since=$(stats_lines)
wait_log "read failed" 30  # the kiosk saw the unplug
wait_idle "$since" "$WAIT_S"
mark turned
wait_go after-shot

# Plug it back in and turn another knob: the kiosk must find it again and show the change.
"$SIM" --uhid --panel-config "$PANEL_CONFIG" --hold-ms 1000 "$TURN2" >"$OUT/sim2.log" 2>&1 ||
  die "the panel simulator failed (replug): $(tail -1 "$OUT/sim2.log")"
since=$(stats_lines)
wait_idle "$since" "$WAIT_S"
mark replugged
wait_go replug-shot

# The display unplugged (the host turns virtio-gpu's output off) and plugged back: the kiosk
# lets the screen go, then takes it again and shows its picture without a restart.
wait_log " disconnected" "$WAIT_S"
mark display-gone
wait_go display-gone-shot
wait_log "after [0-9.]* s without a screen" "$WAIT_S"
mark display-back
wait_go display-back-shot

kill -TERM "$kiosk"
wait "$kiosk"
echo $? >"$OUT/kiosk.rc"
mark done
