#!/usr/bin/env bash
# `cmake --install` into a scratch root gives a kiosk that runs from there: weft and its
# offline helper find the data files under <prefix>/share/weft from their own location (not the
# source tree), WEFT_ASSETS still wins, and the manual and bash completion list every subcommand.
# Usage: installed_tree_test.sh BUILD_DIR INSTALL_PREFIX SOURCE_ASSETS
set -euo pipefail
build=$1 prefix=$2 source_assets=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
DESTDIR="$dir" cmake --install "$build" >/dev/null
root=$dir$prefix
fail() { echo "FAIL: $*"; exit 1; }
unset WEFT_ASSETS

for f in bin/weft libexec/weft/weft-offline libexec/weft/weft-panel-sim lib/systemd/system/weft.service \
         lib/sysusers.d/weft.conf lib/tmpfiles.d/weft.conf lib/udev/rules.d/70-weft-panel.rules \
         share/man/man1/weft.1.gz share/bash-completion/completions/weft share/doc/weft/README.md \
         share/weft/fabrics/velvet.json share/weft/scenes share/weft/envmaps/studio.exr; do
  [ -e "$root/$f" ] || fail "$prefix/$f not installed"
done

# A preset only the installed tree has: the commands list it only if they read <prefix>/share/weft.
cp "$root/share/weft/fabrics/velvet.json" "$root/share/weft/fabrics/only_installed.json"
[ ! -e "$source_assets/fabrics/only_installed.json" ] || fail "the source tree has only_installed.json"
# shellcheck disable=SC2054  # the commas belong to the values
sg=(--view 0.5,0.2,0.8 --sg -0.3,0.1,0.9,20,1,1,1)
# weft-offline (libexec/weft): its share/weft is ../../share/weft.
"$root/bin/weft" eval --fabric only_installed "${sg[@]}" >"$dir/eval.json" 2>"$dir/eval.err" \
  || fail "weft eval --fabric only_installed: $(cat "$dir/eval.err")"
grep -q '"radiance"' "$dir/eval.json" || fail "weft eval printed no radiance: $(cat "$dir/eval.json")"
# weft (bin): its share/weft is ../share/weft; an unknown preset's message lists the ones it sees.
set +e
"$root/bin/weft" panel --fabric no_such_fabric --source none --duration 0 >/dev/null 2>"$dir/panel.err"
set -e
grep -q "only_installed" "$dir/panel.err" || fail "weft panel did not read $prefix/share/weft: $(cat "$dir/panel.err")"
# WEFT_ASSETS comes first.
set +e
WEFT_ASSETS="$source_assets" "$root/bin/weft" eval --fabric only_installed "${sg[@]}" >/dev/null 2>"$dir/env.err"
rc=$?
set -e
if [ "$rc" != 2 ] || ! grep -q "unknown fabric 'only_installed'" "$dir/env.err"; then
  fail "WEFT_ASSETS=$source_assets did not win (exit $rc): $(cat "$dir/env.err")"
fi

# The manual and the completion know every subcommand weft --help lists, and a subcommand's own.
commands=$("$root/bin/weft" --help | awk '/^Subcommands:/ { on = 1; next } on && NF { print $1 }')
[ "$(wc -w <<<"$commands")" -ge 9 ] || fail "weft --help lists only: $commands"
for c in $commands; do
  zgrep -q "^\.SS weft $c\$" "$root/share/man/man1/weft.1.gz" || fail "weft(1) has no section for weft $c"
done
completions=$(PATH="$root/bin:$PATH" bash -c '
  source "$1"
  COMP_WORDS=(weft ""); COMP_CWORD=1; _weft; echo "${COMPREPLY[*]}"
  COMP_WORDS=(weft run --st); COMP_CWORD=2; _weft; echo "${COMPREPLY[*]}"
  COMP_WORDS=(weft bundle ""); COMP_CWORD=2; _weft; echo "${COMPREPLY[*]}"' _ "$root/share/bash-completion/completions/weft")
for c in $commands; do
  grep -qw -- "$c" <<<"$(head -n 1 <<<"$completions")" || fail "completion does not offer $c: $completions"
done
[ "$(sed -n 2p <<<"$completions")" = "--state-dir --stats-every --status-file" ] || fail "weft run --st completes to: $(sed -n 2p <<<"$completions")"
[ "$(sed -n 3p <<<"$completions")" = "info verify" ] || fail "weft bundle completes to: $(sed -n 3p <<<"$completions")"
echo "installed tree under $prefix: assets from share/weft, $(wc -w <<<"$commands") subcommands in weft(1) and the completion"
