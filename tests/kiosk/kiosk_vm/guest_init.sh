#!/bin/busybox sh
# PID 1 of the kiosk VM (runs from the initramfs under busybox): mounts the kernel filesystems,
# loads the modules the host listed in dependency order (virtio + 9p, overlay, bochs + DRM, uhid +
# hid), mounts the host's root read-only over virtio-9p, unpacks the Debian package the host built
# (dpkg-deb -x) and lays it over that root (overlayfs), mounts the test's output folder writable,
# then runs the guest half of the test (tests/kiosk/kiosk_vm/guest_steps.sh) chrooted into the result:
# the host's userspace with the package installed, as on a kiosk.
/bin/busybox --install -s /bin
export PATH=/bin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
. /vm.env  # OUT, GUEST_STEPS, DEB
echo "vm-init: kernel up after $(cut -d' ' -f1 /proc/uptime) s"
while read -r m; do
  insmod "/modules/$m" 2>/dev/null || echo "vm-init: insmod $m failed"
done </modules/order
give_up() {
  echo "vm-init: FAILED: $*"
  # The host learns it from the output folder when that is mounted.
  mkdir -p /out && mount -t 9p -o trans=virtio,version=9p2000.L out /out 2>/dev/null &&
    { echo "vm-init: $*" >>/out/guest.log; touch /out/at-failed; umount /out; }
  poweroff -f
}
mkdir -p /host /root
# The host's root: one export spanning several host filesystems, hence multidevs=remap on the host
# side; cache=loose because it is read-only and does not change under us (much faster under TCG).
mount -t 9p -o trans=virtio,version=9p2000.L,ro,cache=loose,msize=512000 hostroot /host ||
  give_up "cannot mount the host root over 9p"
# The package, unpacked by the host's dpkg-deb into a tmpfs, then over the host's root: the
# package's /usr/bin/weft, /usr/libexec/weft, /usr/share/weft... appear where dpkg would put them.
mount -t proc proc /host/proc
mount -t devtmpfs dev /host/dev
mount -t tmpfs package /host/run
mkdir -p /host/run/root
chroot /host /usr/bin/dpkg-deb -x "$DEB" /run/root || give_up "dpkg-deb -x $DEB failed"
umount /host/proc /host/dev
mount -t overlay weft-root -o lowerdir=/host/run/root:/host /root || give_up "cannot lay the package over the host root"
echo "vm-init: $(basename "$DEB") unpacked over the host root after $(cut -d' ' -f1 /proc/uptime) s"
mount -t proc proc /root/proc
mount -t sysfs sys /root/sys
mount -t devtmpfs dev /root/dev
# What udev would add and bash's process substitution and scripts expect.
ln -sf /proc/self/fd /root/dev/fd
ln -sf /proc/self/fd/0 /root/dev/stdin
ln -sf /proc/self/fd/1 /root/dev/stdout
ln -sf /proc/self/fd/2 /root/dev/stderr
# Scratch space on /run only: a tmpfs over /tmp would hide a checkout or build under /tmp
# (CI machines often have one there). guest_steps.sh points HOME and TMPDIR at /run.
mount -t tmpfs run /root/run
# Last, so an output folder under /run is not hidden by the tmpfs above.
mount -t 9p -o trans=virtio,version=9p2000.L,msize=512000 out "/root$OUT" || echo "vm-init: FAILED to mount the output folder"
echo "vm-init: userspace ready after $(cut -d' ' -f1 /proc/uptime) s"
chroot /root /bin/bash "$GUEST_STEPS" "$OUT"
echo "vm-init: guest steps exited with $?"
sync
poweroff -f
