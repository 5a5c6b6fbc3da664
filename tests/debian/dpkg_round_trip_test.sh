#!/usr/bin/env bash
# The kiosk's package through dpkg itself, in a scratch root (dpkg --root, maintainer scripts
# run chrootless with DPKG_ROOT, as when a system image is built): install creates the user and
# the state directory; an upgrade keeps the operator's edited weft.conf; remove keeps the
# kiosk's state; purge leaves the root as it was before the install (passwd and group
# included), whatever the operator added (enablement, bundle, panel config, drop-in).
# Needs root (dpkg, chown, userdel --root); exit 77 otherwise.
# Usage: dpkg_round_trip_test.sh BUILD_DIR
set -euo pipefail
build=$1
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*"; exit 1; }
[ "$(id -u)" = 0 ] || { echo "SKIPPED: dpkg --root, chown and userdel --root need root"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
deb=$("$here/kiosk_deb.sh" "$build" "$dir/deb")

r=$dir/root
mkdir -p "$r/var/lib/dpkg/info" "$r/var/lib/dpkg/updates" "$r/etc"
touch "$r/var/lib/dpkg/status" "$r/etc/shadow" "$r/etc/gshadow"
printf 'root:x:0:0:root:/root:/bin/sh\n' >"$r/etc/passwd"
printf 'root:x:0:\nvideo:x:44:\ninput:x:105:\nrender:x:106:\n' >"$r/etc/group"
[ -f /etc/login.defs ] && cp /etc/login.defs "$r/etc/"
cp "$r/etc/passwd" "$dir/passwd.before"
cp "$r/etc/group" "$dir/group.before"
# What a purge may leave: dpkg's own database and shadow-utils' backups and lock.
listing() { (cd "$r" && find . | grep -Ev '^\./var/lib/dpkg(/|$)|^\./etc/(passwd|group|shadow|gshadow)-$|^\./etc/\.pwd\.lock$' | sort); }
listing >"$dir/before"
# Dependencies are this machine's business, not the scratch root's.
pkg() { DPKG_ROOT=$r dpkg --root="$r" --force-script-chrootless --force-depends "$@" >>"$dir/dpkg.log" 2>&1 || fail "dpkg $*: $(tail -5 "$dir/dpkg.log")"; }

pkg -i "$deb"
grep -q '^weft:x:[0-9]*:[0-9]*:' "$r/etc/passwd" || fail "install created no user weft: $(cat "$r/etc/passwd")"
uid=$(sed -n 's/^weft:x:\([0-9]*\):.*/\1/p' "$r/etc/passwd")
[ "$(stat -c %u "$r/var/lib/weft")" = "$uid" ] || fail "/var/lib/weft is not the user weft's (uid $uid)"
grep -q '^video:.*weft' "$r/etc/group" || fail "the user weft is not in group video: $(cat "$r/etc/group")"
conf=$(sed -n 1p "$build/debian/debian/conffiles")
[ -f "$r$conf" ] || fail "no $conf after install"

# The operator: settings edited, a bundle, a panel config, a drop-in, the service enabled.
echo 'WEFT_PROBE=camera' >>"$r$conf"
mkdir -p "$r/etc/weft" "$r/etc/systemd/system/multi-user.target.wants" "$r/etc/systemd/system/weft.service.d"
echo '{}' >"$r/etc/weft/panel.json"
echo '[Service]' >"$r/etc/systemd/system/weft.service.d/override.conf"
ln -s /usr/lib/systemd/system/weft.service "$r/etc/systemd/system/multi-user.target.wants/weft.service"
echo bundle >"$r/var/lib/weft/showroom.weft"

pkg -i "$deb"  # an upgrade (to the same version): postinst configure with the old version
grep -qx 'WEFT_PROBE=camera' "$r$conf" || fail "the upgrade lost the operator's edit of $conf"
pkg -r weft
[ -f "$r/var/lib/weft/showroom.weft" ] && [ -f "$r$conf" ] && grep -q '^weft:' "$r/etc/passwd" ||
  fail "remove (not purge) deleted the kiosk's state, settings or user"
[ ! -e "$r/usr/bin/weft" ] || fail "remove left /usr/bin/weft"
pkg -P weft
listing >"$dir/after"
# /etc/systemd/system and /var/lib/systemd exist on any systemd machine: the operator's and
# deb-systemd-helper's folders, not the package's leftovers.
diff "$dir/before" "$dir/after" | grep '^>' | grep -Ev '^> \./(etc/systemd|etc/systemd/system|var/lib/systemd)$' >"$dir/left" || true
[ ! -s "$dir/left" ] || fail "purge left: $(tr '\n' ' ' <"$dir/left")"
cmp -s "$dir/passwd.before" "$r/etc/passwd" || fail "purge left /etc/passwd as: $(cat "$r/etc/passwd")"
cmp -s "$dir/group.before" "$r/etc/group" || fail "purge left /etc/group as: $(cat "$r/etc/group")"
echo "dpkg round trip in a scratch root: install (user weft uid $uid, /var/lib/weft), upgrade kept the edited conffile, remove kept the state, purge left nothing"
