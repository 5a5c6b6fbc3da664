#!/usr/bin/env bash
# The weft package's maintainer scripts (debian/debian), run as dpkg runs them, two ways:
#  root  DPKG_ROOT set to a scratch root holding the kiosk package's files (`dpkg --root`): the
#        real deb-systemd-helper records the unit's links; after the operator's enable and
#        edits, purge leaves no state, settings, drop-in, link or record behind and deletes the
#        user and group; remove keeps the state. Nothing touches this machine's services.
#  live  a private mount namespace whose /run says systemd and udev are running (unshare; exit
#        77 where it is not allowed): a fresh install starts nothing, an upgrade try-restarts
#        the kiosk, remove stops it and an upgrade's prerm does not.
# The commands that would change this machine (systemctl, udevadm, systemd-sysusers, userdel,
# ...) are replaced by recorders on PATH, and the test reads what they were asked to do.
# Usage: maintainer_scripts_test.sh root|live SCRIPTS_DIR BUILD_DIR
set -euo pipefail
mode=$1 scripts=$2 build=$3
fail() { echo "FAIL: $*"; exit 1; }
for s in postinst prerm postrm; do sh -n "$scripts/$s" || fail "$s: syntax"; done

dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
log=$dir/calls
mkdir -p "$dir/bin"
recorded=(systemctl deb-systemd-invoke udevadm systemd-sysusers systemd-tmpfiles userdel groupdel)
[ "$mode" = live ] && recorded+=(deb-systemd-helper)  # without DPKG_ROOT the real one would edit /etc
for c in "${recorded[@]}"; do
  printf '#!/bin/sh\necho "%s $*" >>"%s"\n' "$c" "$log" >"$dir/bin/$c"
  chmod +x "$dir/bin/$c"
done
run() {  # SCRIPT ARGS...: as dpkg would, with the recorders first on PATH
  : >"$log"
  PATH="$dir/bin:$PATH" DPKG_MAINTSCRIPT_PACKAGE=weft DPKG_MAINTSCRIPT_NAME=$1 sh -e "$scripts/$1" "${@:2}" ||
    fail "$1 $* exited $?"
}
called() { grep -qx -- "$1" "$log" || fail "expected '$1'; the scripts ran: $(tr '\n' ';' <"$log")"; }
not_called() { ! grep -q -- "$1" "$log" || fail "unexpected '$(grep -- "$1" "$log" | head -1)'"; }

if [ "$mode" = root ]; then
  r=$dir/root
  DESTDIR="$r" cmake --install "$build" --prefix /usr --component weft >/dev/null
  mkdir -p "$r/etc/weft" "$r/etc/systemd/system/multi-user.target.wants" "$r/etc/systemd/system/weft.service.d" "$r/var/lib/weft/last-good"
  printf 'root:x:0:0::/root:/bin/sh\nweft:x:998:998:Weft showroom kiosk:/var/lib/weft:/usr/sbin/nologin\n' >"$r/etc/passwd"
  printf 'root:x:0:\nvideo:x:44:weft\nweft:x:998:\n' >"$r/etc/group"
  export DPKG_ROOT=$r

  run postinst configure
  called "systemd-sysusers --root=$r weft.conf"
  called "systemd-tmpfiles --root=$r --create weft.conf"
  not_called "systemctl"; not_called "deb-systemd-invoke"; not_called "udevadm"
  record="$r/var/lib/systemd/deb-systemd-helper-enabled/weft.service.dsh-also"
  grep -qx /etc/systemd/system/multi-user.target.wants/weft.service "$record" ||
    fail "deb-systemd-helper recorded no link for weft.service: $(cat "$record" 2>/dev/null)"

  # The operator's doing: enabled, a bundle and knobs, their own panel config and a drop-in.
  ln -s /usr/lib/systemd/system/weft.service "$r/etc/systemd/system/multi-user.target.wants/weft.service"
  touch "$r/var/lib/weft/showroom.weft" "$r/var/lib/weft/knobs.json" "$r/var/lib/weft/last-good/showroom.weft"
  echo '{}' >"$r/etc/weft/panel.json"
  echo '[Service]' >"$r/etc/systemd/system/weft.service.d/override.conf"

  run prerm remove
  not_called "deb-systemd-invoke"
  run postrm remove
  [ -e "$r/var/lib/weft/showroom.weft" ] && [ -e "$r/etc/weft/panel.json" ] || fail "remove (not purge) deleted the kiosk's state or settings"
  not_called "userdel"

  rm -f "$r/etc/weft/weft.conf"  # dpkg deletes the conffile itself before postrm purge
  run postrm purge
  for gone in /var/lib/weft /etc/weft /etc/systemd/system/weft.service.d /etc/systemd/system/multi-user.target.wants/weft.service \
              /var/lib/systemd/deb-systemd-helper-enabled/weft.service.dsh-also; do
    [ ! -e "$r$gone" ] && [ ! -L "$r$gone" ] || fail "purge left $gone"
  done
  called "userdel --root $r weft"
  called "groupdel --root $r weft"
  not_called "systemctl"; not_called "udevadm"
  echo "maintainer scripts under DPKG_ROOT: postinst records the unit's link; remove keeps the state; purge removes state, settings, drop-in, link, record, user and group"
  exit 0
fi

[ "$mode" = live ] || fail "mode must be root or live, not $mode"
# A /run of our own in which systemd and udev are running; nothing else of this machine changes.
if ! unshare -rm true 2>/dev/null; then
  echo "SKIPPED: no private mount namespace here (unshare -rm)"
  exit 77
fi
export -f run called not_called fail
export dir log scripts
unshare -rm bash -euo pipefail -c '
  mount -t tmpfs weft-test /run
  mkdir -p /run/systemd/system /run/udev
  unset DPKG_ROOT
  run postinst configure
  called "systemctl --system daemon-reload"
  called "udevadm control --reload-rules"
  called "deb-systemd-helper update-state weft.service"
  not_called "deb-systemd-invoke"
  run postinst configure 0.1.0-0
  called "deb-systemd-invoke try-restart weft.service"
  not_called "deb-systemd-invoke start"
  run prerm upgrade 0.1.0-2
  not_called "deb-systemd-invoke"
  run prerm remove
  called "deb-systemd-invoke stop weft.service"
'
echo "maintainer scripts with systemd running: fresh install starts nothing; upgrade try-restarts weft.service; remove stops it, an upgrade does not"
