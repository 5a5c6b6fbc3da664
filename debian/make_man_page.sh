#!/usr/bin/env bash
# weft(1) from the program's own help, so the page never drifts from the code: help2man formats
# `weft --help` and `weft --version`; each subcommand's --help follows as a section of its own.
# Usage: make_man_page.sh WEFT_BINARY OUT_FILE
set -euo pipefail
weft=$(realpath "$1") out=$2
include=$(mktemp)
trap 'rm -f "$include"' EXIT
# Run as plain `weft` (on PATH) so usage lines read "weft ...", not the build folder's path.
PATH="$(dirname "$weft"):$PATH"
export PATH
commands=$(weft --help | awk '/^Subcommands:/ { on = 1; next } on && NF { print $1 }')
[ -n "$commands" ] || { echo "make_man_page: no subcommands in 'weft --help'" >&2; exit 1; }
roff_escape() { sed -e 's/\\/\\e/g' -e 's/^\([.'"'"']\)/\\\&\1/'; }
{
  echo "[COMMANDS]"
  for c in $commands; do
    echo ".SS weft $c"
    echo ".nf"
    weft "$c" --help | roff_escape
    echo ".fi"
  done
  cat <<'ROFF'
[FILES]
.TP
.I /etc/weft/weft.conf
The kiosk service's settings (bundle, panel configuration, light probe, exposure, extra flags).
.TP
.I /var/lib/weft
The kiosk's state: the bundle it shows, its last good copy, the knob positions.
.TP
.I /run/weft/status.json
The running kiosk's health (\fBweft status\fR), rewritten every 2 seconds.
.TP
.I /usr/share/weft
Fabric presets, scenes and environment maps; \fBWEFT_ASSETS\fR names another folder.
[ENVIRONMENT]
.TP
.B WEFT_ASSETS
Folder of fabrics/, scenes/ and envmaps/ used instead of the installed ones.
.TP
.B RUNTIME_DIRECTORY
Set by systemd from the unit's RuntimeDirectory; \fBweft run\fR writes its status file there.
.TP
.B JOURNAL_STREAM
Set by systemd when standard error is the journal; log lines then carry their priority.
[SEE ALSO]
.BR systemctl (1),
.BR journalctl (1),
/usr/share/doc/weft/README.md
ROFF
} > "$include"
help2man --no-info --section=1 --name="microcylinder cloth rendering for showroom kiosks" \
  --include="$include" --output="$out" weft
