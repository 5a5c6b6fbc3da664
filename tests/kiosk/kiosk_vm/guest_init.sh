#!/bin/busybox sh
# PID 1 of the kiosk VM (runs from the initramfs under busybox): mounts the kernel filesystems,
# loads the modules the host listed in dependency order (virtio + 9p, bochs + DRM, uhid + hid),
# mounts the host's root read-only over virtio-9p and the test's output folder writable over it,
# then runs the guest half of the test (tests/kiosk/kiosk_vm/guest_steps.sh) chrooted into the host root.
/bin/busybox --install -s /bin
export PATH=/bin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
. /vm.env  # OUT, GUEST_STEPS
echo "vm-init: kernel up after $(cut -d' ' -f1 /proc/uptime) s"
while read -r m; do
  insmod "/modules/$m" 2>/dev/null || echo "vm-init: insmod $m failed"
done </modules/order
mkdir -p /host
# The host's root: one export spanning several host filesystems, hence multidevs=remap on the host
# side; cache=loose because it is read-only and does not change under us (much faster under TCG).
if ! mount -t 9p -o trans=virtio,version=9p2000.L,ro,cache=loose,msize=512000 hostroot /host; then
  echo "vm-init: FAILED to mount the host root over 9p"; poweroff -f
fi
mount -t proc proc /host/proc
mount -t sysfs sys /host/sys
mount -t devtmpfs dev /host/dev
# What udev would add and bash's process substitution and scripts expect.
ln -sf /proc/self/fd /host/dev/fd
ln -sf /proc/self/fd/0 /host/dev/stdin
ln -sf /proc/self/fd/1 /host/dev/stdout
ln -sf /proc/self/fd/2 /host/dev/stderr
# Scratch space on /run only: a tmpfs over /tmp would hide a checkout or build under /tmp
# (CI machines often have one there). guest_steps.sh points HOME and TMPDIR at /run.
mount -t tmpfs run /host/run
# Last, so an output folder under /run is not hidden by the tmpfs above.
mount -t 9p -o trans=virtio,version=9p2000.L,msize=512000 out "/host$OUT" || echo "vm-init: FAILED to mount the output folder"
echo "vm-init: userspace ready after $(cut -d' ' -f1 /proc/uptime) s"
chroot /host /bin/bash "$GUEST_STEPS" "$OUT"
echo "vm-init: guest steps exited with $?"
sync
poweroff -f
