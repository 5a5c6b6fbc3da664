#!/bin/sh
# Runs filament_peer (or any command) with an X display for Filament's GLX backend: the session's
# own, or a virtual one from Xvfb (Debian's xvfb) when DISPLAY is unset. Without either the
# program itself says it is skipped.
if [ -z "$DISPLAY" ] && command -v xvfb-run >/dev/null 2>&1; then
  exec xvfb-run -a -s "-screen 0 640x480x24" "$@"
fi
exec "$@"
