#!/usr/bin/env bash
# End to end on a real kernel, from the Debian package: builds the .deb from BUILD_DIR's install
# rules (the kiosk's package `weft` alone, prefix /usr), boots Debian 12's kernel under QEMU (TCG) with this machine's root
# shared read-only over virtio-9p and the package's contents (dpkg-deb -x) laid over it, runs the
# packaged /usr/bin/weft on virtio-gpu's /dev/dri/card0 (real DRM/KMS + GBM + EGL, Mesa kms_swrast)
# and the packaged panel simulator as a real uhid device, turns a knob, unplugs and replugs the
# panel, then the display itself, and checks the screen through QEMU's `screendump`.
# How to run it and what it proves: tests/kiosk/KIOSK_VM.md.
#
# usage: kiosk_vm_test.sh WEFT BUILD_DIR UHID_PANEL_TEST OUT_DIR
#   WEFT: the build tree's weft (bakes the bundle and renders the references on the host)
# exit: 0 pass, 1 fail, 77 skipped (no qemu or no kernel package obtainable).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
[ $# -eq 4 ] || { sed -n 2,10p "$0"; exit 2; }
weft=$(readlink -f "$1")
build=$(readlink -f "$2")
uhid_test=$(readlink -f "$3")
mkdir -p "$4" || exit 2
work=$(readlink -f "$4")
python=/usr/bin/python3  # Debian's, not whatever is first on PATH (frames.py needs only the stdlib)
frames_py="$here/kiosk_vm/frames.py"
SKIP=77
# Small mode: llvmpipe under TCG is slow and bochs can only scan out what fits its VRAM.
MODE_W=${KIOSK_VM_WIDTH:-320}
MODE_H=${KIOSK_VM_HEIGHT:-240}
VM_TIMEOUT=${KIOSK_VM_TIMEOUT:-420}

t0=$(date +%s.%N)
elapsed() { echo "$(date +%s.%N) $t0" | awk '{printf "%.1f", $1 - $2}'; }
say() { echo "kiosk-vm [$(elapsed) s]: $*"; }
fail() {
  say "FAIL: $*"
  for f in "$work/out/guest.log" "$work/out/kiosk.log" "$work/console.log"; do
    [ -s "$f" ] && { echo "--- tail of $f"; tail -15 "$f"; }
  done
  exit 1
}
skip() { say "SKIPPED: $*"; exit $SKIP; }

# 1. Tools: qemu, busybox (the initramfs shell), kmod (module order), cpio. Installed the way
#    setup.sh installs everything; skip only when they truly cannot be had.
need=()
command -v qemu-system-x86_64 >/dev/null || need+=(qemu-system-x86)
dpkg-query -W -f='${Status}' busybox-static 2>/dev/null | grep -q "install ok installed" || need+=(busybox-static)
command -v depmod >/dev/null || need+=(kmod)
command -v cpio >/dev/null || need+=(cpio)
command -v dbus-daemon >/dev/null || need+=(dbus-daemon)  # the display's plug (QEMU's D-Bus display)
if [ ${#need[@]} -gt 0 ]; then
  say "installing ${need[*]}"
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo -n"
  { $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}"; } \
    >"$work/apt.log" 2>&1 || skip "could not install ${need[*]} (see $work/apt.log)"
fi

# 2. The kernel: Debian 12's linux-image-amd64, fetched with apt and unpacked here (no install).
kdir="$work/kernel"
if ! ls "$kdir"/boot/vmlinuz-* >/dev/null 2>&1; then
  kpkg=$(apt-cache depends linux-image-amd64 2>/dev/null | awk '/Depends: linux-image-/{print $2; exit}')
  [ -n "$kpkg" ] || skip "apt knows no linux-image-amd64 (apt-get update?)"
  say "fetching $kpkg"
  rm -rf "$kdir" && mkdir -p "$kdir/deb"
  (cd "$kdir/deb" && apt-get download "$kpkg" >"$work/apt-kernel.log" 2>&1) || skip "apt-get download $kpkg failed (see $work/apt-kernel.log)"
  dpkg-deb -x "$kdir"/deb/*.deb "$kdir" || fail "cannot unpack $kpkg"
  rm -rf "$kdir/deb"
fi
vmlinuz=$(ls "$kdir"/boot/vmlinuz-* | head -1)
kver=${vmlinuz##*/vmlinuz-}
[ -f "$kdir/lib/modules/$kver/modules.dep" ] || depmod -b "$kdir" "$kver" || fail "depmod failed"

# 3. The initramfs: static busybox, our init, the modules in dependency order.
ird="$work/initramfs"
rm -rf "$ird" && mkdir -p "$ird"/{bin,proc,sys,dev,modules}
cp /bin/busybox "$ird/bin/busybox"
cp "$here/kiosk_vm/guest_init.sh" "$ird/init" && chmod +x "$ird/init"
: >"$ird/modules/order"
for m in virtio_pci 9pnet_virtio 9p overlay virtio_gpu uhid hid_generic; do
  modprobe -d "$kdir" -S "$kver" --show-depends "$m" >"$work/deps.txt" 2>&1 || fail "no module $m in $kver: $(cat "$work/deps.txt")"
  while read -r _ ko _; do
    name=$(basename "$ko")
    grep -qx "$name" "$ird/modules/order" && continue
    cp "$ko" "$ird/modules/$name"
    echo "$name" >>"$ird/modules/order"
  done < <(grep '^insmod ' "$work/deps.txt")
done
say "kernel $kver, $(wc -l <"$ird/modules/order") modules for the initramfs"

# 4. The kiosk's Debian package alone, `weft` (not weft-tools, not weft-probe-camera): the files
#    of `./setup.sh package`'s weft_*.deb, made by tests/debian/kiosk_deb.sh from the same
#    install component (BUILD_DIR is not reconfigured). The guest unpacks the .deb over its
#    root (kiosk_vm/guest_init.sh).
pkg="$work/package"
rm -rf "$pkg"
deb=$("$repo/debian/kiosk_deb.sh" "$build" "$pkg") || fail "cannot make the kiosk package"
dpkg-deb -c "$deb" | awk '{print $NF}' >"$work/package.files"
for f in ./usr/bin/weft ./usr/libexec/weft/weft-panel-sim \
         ./usr/share/weft/fabrics/linen_plain.json ./usr/lib/systemd/system/weft.service; do
  grep -qx -- "$f" "$work/package.files" || fail "the package has no ${f#.}"
done
! grep -E 'weft-offline|libweft-probe' "$work/package.files" || fail "the kiosk package holds the above (weft-tools', weft-probe-camera's)"
[ ! -e /usr/libexec/weft/weft-offline ] || fail "this machine has /usr/libexec/weft/weft-offline: the guest would see it under the package"
prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$build/CMakeCache.txt")
[ "$prefix" = /usr ] || say "note: $build is configured for $prefix, so the package's unit and weft.conf name $prefix paths; the guest has no systemd and runs /usr/bin/weft itself"
say "package $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB, $(wc -l <"$work/package.files") entries)"

# 5. On the host: the bundle, the knob scripts, and the headless reference renders the VM's
#    screen is checked against (same bundle, same knob turns, same size, no VM).
shots="$work/shots"
rm -rf "$shots" "$work/ref" && mkdir -p "$shots" "$work/ref"
bundle="$work/showroom.weft"
# The scene alone (no weighting tables): the VM proves the device paths; sgpoint keeps TCG frames short.
"$weft" bake --scene pillow --fabric linen_plain --no-tables --out "$bundle" >"$work/bake.log" 2>&1 || fail "weft bake failed: $(tail -3 "$work/bake.log")"
cat >"$work/panel.json" <<JSON
{"sources": ["hid"], "hid": {"vendor_id": "0x1209", "product_id": "0x57ef"}}
JSON
printf 'turn 0 +20\n' >"$work/turn1.knobs"          # hue +60 degrees, 80 ms a detent (no acceleration)
printf 'turn 1 -8\n' >"$work/turn2.knobs"           # brightness halved
cat "$work/turn1.knobs" "$work/turn2.knobs" >"$work/turn12.knobs"
reference() {  # NAME [KNOB_SCRIPT]
  local panel=none
  [ -n "${2:-}" ] && panel="sim:$2"
  "$weft" run --bundle "$bundle" --state-dir "$work/ref/$1" --display headless --width "$MODE_W" --height "$MODE_H" \
    --turntable 0 --panel "$panel" --sim-speed 10 --frames 200 --stats-every 0 \
    --screenshot "$work/ref/$1.png" >"$work/ref/$1.log" 2>&1 || fail "reference render $1 failed: $(tail -2 "$work/ref/$1.log")"
}
reference before
reference after "$work/turn1.knobs"
reference replug "$work/turn12.knobs"
say "bundle and host reference renders ready"

out="$work/out"
rm -rf "$out" && mkdir -p "$out"
# The guest runs the package's programs (its root is this machine's with the .deb unpacked over it);
# the uhid unit test is a test binary, from the build tree.
cat >"$out/guest.env" <<ENV
WEFT=/usr/bin/weft
SIM=/usr/libexec/weft/weft-panel-sim
UHID_TEST=$uhid_test
BUNDLE=$bundle
PANEL_CONFIG=$work/panel.json
TURN1=$work/turn1.knobs
TURN2=$work/turn2.knobs
WAIT_S=$VM_TIMEOUT
ENV
printf 'OUT=%s\nGUEST_STEPS=%s\nDEB=%s\n' "$out" "$here/kiosk_vm/guest_steps.sh" "$deb" >"$ird/vm.env"
(cd "$ird" && find . | cpio -o -H newc --quiet | gzip -1) >"$work/initramfs.cpio.gz" || fail "cannot pack the initramfs"

# 6. Boot. TCG (no KVM here): 2 vCPUs, 2 GiB; virtio-gpu advertises MODE_W x MODE_H as its
#    preferred mode through EDID; the monitor answers screendump on a socket. The display's plug:
#    QEMU's D-Bus display on a bus of the test's own, whose console's SetUIInfo turns virtio-gpu's
#    output off (0x0: the guest's connector disconnected, as a cable pulled) and on again.
mon="$work/monitor.sock"
rm -f "$mon" "$work/console.log"
dbus-daemon --session --fork --print-address=3 --print-pid=4 3>"$work/dbus.address" 4>"$work/dbus.pid" ||
  fail "cannot start a D-Bus daemon for QEMU's display"
bus=$(cat "$work/dbus.address")
display_plug() {  # WIDTH HEIGHT; 0 0: unplugged
  busctl --address="$bus" call org.qemu /org/qemu/Display1/Console_0 org.qemu.Display1.Console SetUIInfo qqiiuu 0 0 0 0 "$1" "$2"
}
boot_start=$(date +%s.%N)
DBUS_SESSION_BUS_ADDRESS=$bus qemu-system-x86_64 -nodefaults -no-reboot -display dbus,p2p=no \
  -accel tcg,thread=multi -cpu "${KIOSK_VM_CPU:-qemu64}" -smp 2 -m 2048 \
  -kernel "$vmlinuz" -initrd "$work/initramfs.cpio.gz" \
  -append "console=ttyS0 loglevel=4 panic=-1 mitigations=off rdinit=/init" \
  -device "virtio-gpu-pci,xres=$MODE_W,yres=$MODE_H" \
  -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap \
  -virtfs "local,path=$out,mount_tag=out,security_model=none" \
  -monitor "unix:$mon,server=on,wait=off" \
  -serial "file:$work/console.log" &
qemu_pid=$!
trap 'kill $qemu_pid $(cat "$work/dbus.pid") 2>/dev/null' EXIT
trap 'exit 1' TERM INT  # so a ctest timeout or ^C still takes the VM down
since_boot() { echo "$(date +%s.%N) $boot_start" | awk '{printf "%.1f", $1 - $2}'; }

guest_reached() {  # STEP: wait until the guest touches at-STEP (or fails, or the VM is gone)
  local i
  for ((i = 0; i < VM_TIMEOUT * 5; i++)); do
    [ -e "$out/at-$1" ] && { say "guest: $1 (${2:-} $(since_boot) s after qemu started)"; return 0; }
    [ -e "$out/at-failed" ] && fail "the guest gave up before '$1': $(tail -1 "$out/guest.log")"
    kill -0 $qemu_pid 2>/dev/null || fail "the VM stopped before '$1' (console: $work/console.log)"
    sleep 0.2
  done
  fail "the guest did not reach '$1' within ${VM_TIMEOUT} s"
}
screendump() {  # NAME
  local t=$(date +%s.%N)
  "$python" "$frames_py" shot "$mon" "$shots/$1.ppm" || fail "screendump $1 failed"
  "$python" "$frames_py" png "$shots/$1.ppm" "$shots/$1.png" || fail "cannot convert $1"
  say "screendump $1 took $(echo "$(date +%s.%N) $t" | awk '{printf "%.2f", $1 - $2}') s -> $shots/$1.png"
}

guest_reached userspace
# The console's size as the guest sees it already: from here on 0x0 is a change (an unplug).
display_plug "$MODE_W" "$MODE_H" >/dev/null || fail "QEMU's D-Bus display does not answer SetUIInfo"
guest_reached first-frame
screendump vm_before
touch "$out/go-before-shot"
guest_reached turned
screendump vm_after
touch "$out/go-after-shot"
guest_reached replugged
screendump vm_replug
touch "$out/go-replug-shot"
display_plug 0 0 >/dev/null || fail "cannot unplug the display (SetUIInfo 0x0)"
unplugged=$(date +%s.%N)
guest_reached display-gone "display unplugged; the kiosk let it go"
say "the kiosk let the display go $(echo "$(date +%s.%N) $unplugged" | awk '{printf "%.1f", $1 - $2}') s after the unplug (host clock, 0.2 s polling)"
screendump vm_display_gone
display_plug "$MODE_W" "$MODE_H" >/dev/null || fail "cannot plug the display back (SetUIInfo)"
plugged=$(date +%s.%N)
touch "$out/go-display-gone-shot"
guest_reached display-back "display plugged back; the kiosk showed its picture again"
back_s=$(echo "$(date +%s.%N) $plugged" | awk '{printf "%.1f", $1 - $2}')
say "display back on screen $back_s s after the replug (host clock, 0.2 s polling)"
screendump vm_display_back
touch "$out/go-display-back-shot"
guest_reached done
wait $qemu_pid
trap - EXIT TERM INT
say "VM powered off $(since_boot) s after qemu started"

# 7. Verdict: the package was what ran, the kiosk's own account, then the pictures.
status=0
grep -q "^weft: /usr/bin/weft from the package" "$out/guest.log" || { say "FAIL: the guest did not run the package's /usr/bin/weft"; status=1; }
grep -q "install the weft-tools package" "$out/eval.log" 2>/dev/null ||
  { say "FAIL: weft eval on the kiosk package alone did not ask for weft-tools: $(tail -2 "$out/eval.log" 2>/dev/null)"; status=1; }
grep -q "install the weft-probe-camera package" "$out/probe.log" 2>/dev/null ||
  { say "FAIL: weft probe on the kiosk package alone did not ask for weft-probe-camera: $(tail -2 "$out/probe.log" 2>/dev/null)"; status=1; }
echo "--- kiosk log (guest) ---"; grep -v 'stats: ' "$out/kiosk.log"; echo "---"
[ "$(cat "$out/uhid_test.rc")" = 0 ] || { say "FAIL: the real-uhid unit test failed in the guest:"; cat "$out/uhid_test.log"; status=1; }
grep -q "PASSED.*1 test" "$out/uhid_test.log" || { say "FAIL: the real-uhid unit test did not run in the guest"; status=1; }
[ "$(cat "$out/kiosk.rc")" = 0 ] || { say "FAIL: weft run exited with $(cat "$out/kiosk.rc")"; status=1; }
grep -q "display card0 " "$out/kiosk.log" || { say "FAIL: the kiosk did not run on the KMS display card0"; status=1; }
grep -q "display card0 .* disconnected" "$out/kiosk.log" || { say "FAIL: the kiosk did not see the display unplugged"; status=1; }
[ "$(grep -c "^weft run: display card0 Virtual-1 " "$out/kiosk.log")" -ge 2 ] || { say "FAIL: the kiosk did not take the display again"; status=1; }
[ "$(grep -c 'USB knob panel 1209:57ef connected' "$out/kiosk.log")" -ge 2 ] ||
  { say "FAIL: the kiosk did not connect to the panel twice (plug, replug)"; status=1; }
cmp -s "$out/state/knobs.json" "$work/ref/replug/knobs.json" ||
  { say "FAIL: the VM kiosk's knob state differs from the reference's:"; diff "$out/state/knobs.json" "$work/ref/replug/knobs.json"; status=1; }
"$python" "$frames_py" check "$work/ref/before.png" "$work/ref/after.png" "$shots/vm_before.ppm" "$shots/vm_after.ppm" "knob turn" || status=1
"$python" "$frames_py" check "$work/ref/after.png" "$work/ref/replug.png" "$shots/vm_after.ppm" "$shots/vm_replug.ppm" "after replug" || status=1

echo "--- timings (TCG, 2 vCPUs) ---"
awk '{printf "guest uptime %7.2f s: %s\n", $1, $2}' "$out/marks"
grep -E "first frame after|stopping after" "$out/kiosk.log"
"$python" "$frames_py" back "$shots/vm_replug.ppm" "$shots/vm_display_gone.ppm" "$shots/vm_display_back.ppm" "display replug" || status=1
say "screenshots: $shots/vm_before.png $shots/vm_after.png $shots/vm_replug.png $shots/vm_display_gone.png $shots/vm_display_back.png"
[ $status -eq 0 ] && say "PASS" || say "FAIL"
exit $status
