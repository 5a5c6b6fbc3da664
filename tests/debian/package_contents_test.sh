#!/usr/bin/env bash
# The three packages' contents, from the install components CPack packages (debian/CMakeLists.txt),
# without building a .deb: `cmake --install --component` of each into its own scratch root.
#  - together the components hold exactly what `cmake --install` installs, each file in one;
#  - weft (the kiosk) has weft, the unit, rule, data and manual, and no weft-offline, no plugin,
#    and none of its programs needs Embree, TBB, OpenMP or libcamera (ELF NEEDED);
#  - weft-tools holds weft-offline (which does need Embree: the NEEDED check sees it);
#  - weft-probe-camera holds the plugin (which needs libcamera);
#  - every package has its copyright and changelog.Debian.gz, of the packages' version;
#  - the kiosk alone: `weft probe` and `weft eval` fail with a message naming the package to
#    install, `weft run --probe camera` shows its frame on the bundle's light and logs what to
#    install; with the plugin added, `weft probe` reaches libcamera.
# Usage: package_contents_test.sh BUILD_DIR INSTALL_PREFIX CHANGELOG
set -euo pipefail
build=$1 prefix=$2 changelog=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
unset WEFT_ASSETS

packages=(weft weft-tools weft-probe-camera)
DESTDIR="$dir/all" cmake --install "$build" >/dev/null
for p in "${packages[@]}"; do
  DESTDIR="$dir/$p" cmake --install "$build" --component "$p" >/dev/null
  (cd "$dir/$p" && find . -type f -o -type l | sed 's|^\.||' | sort) >"$dir/$p.files"
done
(cd "$dir/all" && find . -type f -o -type l | sed 's|^\.||' | sort) >"$dir/all.files"

# Each installed file in exactly one package.
sort "$dir"/weft*.files | uniq -d >"$dir/twice"
[ ! -s "$dir/twice" ] || fail "files in two packages: $(head -3 "$dir/twice" | tr '\n' ' ')"
sort "$dir"/weft*.files | comm -23 "$dir/all.files" - >"$dir/nowhere"
[ ! -s "$dir/nowhere" ] || fail "installed but in no package (an install rule without COMPONENT?): $(head -3 "$dir/nowhere" | tr '\n' ' ')"

has() {  # PACKAGE PATH-REGEX
  grep -Eq "^$2\$" "$dir/$1.files" || fail "package $1 has no ${2} ($(wc -l <"$dir/$1.files") files)"
}
lacks() {  # PACKAGE PATH-REGEX
  ! grep -Eq "$2" "$dir/$1.files" || fail "package $1 holds $(grep -E "$2" "$dir/$1.files" | head -1)"
}
p=$prefix
for f in "$p/bin/weft" "$p/libexec/weft/weft-panel-sim" "$p/lib/systemd/system/weft.service" "$p/lib/sysusers.d/weft.conf" \
         "$p/lib/tmpfiles.d/weft.conf" "$p/lib/udev/rules.d/70-weft-panel.rules" "$p/share/man/man1/weft.1.gz" \
         "$p/share/weft/fabrics/linen_plain.json" "$p/share/weft/envmaps/studio.exr" "$p/share/doc/weft/README.md" \
         "$p/share/bash-completion/completions/weft" ".*/weft/weft.conf"; do
  has weft "$f"
done
lacks weft 'weft-offline|libweft-probe|embree|tbb|gomp|camera'
lacks weft 'man1/weft\.1$'  # the manual only compressed
has weft-tools "$p/libexec/weft/weft-offline"
has weft-probe-camera "$p/lib(/[a-z0-9_]+-linux-[a-z0-9_]+)?/weft/libweft-probe-libcamera\.so"
for q in weft-tools weft-probe-camera; do
  others=$(grep -Ev "weft-offline$|libweft-probe-libcamera\.so$|/share/doc/$q/|/share/lintian/overrides/$q\$" "$dir/$q.files" || true)
  [ -z "$others" ] || fail "package $q holds more than its program and doc: $others"
done

# The packages' version: the changelog's first entry (debian/CMakeLists.txt checks it against the project's).
version=$(sed -n '1s/^weft (\([^)]*\)).*/\1/p' "$changelog")
[ -n "$version" ] || fail "no version on the first line of $changelog"
for q in "${packages[@]}"; do
  doc="$dir/$q$p/share/doc/$q"
  grep -q '^Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/$' "$doc/copyright" ||
    fail "$q: no machine-readable copyright in $p/share/doc/$q"
  [ "$(zcat "$doc/changelog.Debian.gz" | head -n 1 | sed 's/^weft (\([^)]*\)).*/\1/')" = "$version" ] ||
    fail "$q: changelog.Debian.gz does not start with version $version"
done

# ELF NEEDED of every program and library in a package.
needed() {  # PACKAGE: prints "file: library" lines
  local f
  while read -r f; do
    [ "$(head -c 4 "$dir/$1$f" | od -An -c | tr -d ' ')" = '177ELF' ] || continue
    readelf -d "$dir/$1$f" | sed -n "s|.*(NEEDED).*\[\(.*\)\]|$f: \1|p"
  done <"$dir/$1.files"
}
needed weft >"$dir/weft.needed"
grep -q "/bin/weft: libc.so" "$dir/weft.needed" || fail "readelf found no NEEDED in weft: $(head -3 "$dir/weft.needed")"
! grep -Ei 'embree|tbb|gomp|camera|draco|meshoptimizer' "$dir/weft.needed" || fail "the kiosk package's programs need the libraries above"
needed weft-tools | grep -q 'weft-offline: libembree' || fail "weft-offline needs no Embree: is the NEEDED check reading anything?"
needed weft-tools | grep -q 'weft-offline: libdraco' || fail "weft-offline needs no Draco: the glTF importer is not where the tools are"
needed weft-probe-camera | grep -q 'libweft-probe-libcamera.so: libcamera.so' || fail "the plugin does not need libcamera"

# The kiosk package alone, as on a kiosk without the others.
root=$dir/weft$p
set +e
"$root/bin/weft" probe --frames 1 >"$dir/probe.out" 2>&1
rc=$?
"$root/bin/weft" eval --fabric linen_plain --view 0.5,0.2,0.8 --sg -0.3,0.1,0.9,20,1,1,1 >"$dir/eval.out" 2>&1
eval_rc=$?
set -e
[ "$rc" = 1 ] && grep -q "libweft-probe-libcamera.so is not installed; install the weft-probe-camera package" "$dir/probe.out" ||
  fail "weft probe without its plugin (exit $rc): $(cat "$dir/probe.out")"
[ "$eval_rc" = 1 ] && grep -q "install the weft-tools package" "$dir/eval.out" ||
  fail "weft eval without weft-tools (exit $eval_rc): $(cat "$dir/eval.out")"
# The kiosk set to a camera probe runs on the bundle's light and says in the journal what to install.
"$build/render/app/weft" bake --scene pillow --fabric linen_plain --no-tables --out "$dir/pillow.weft" >"$dir/bake.out" 2>&1 ||
  fail "weft bake (build tree): $(tail -3 "$dir/bake.out")"
set +e
"$root/bin/weft" run --bundle "$dir/pillow.weft" --state-dir "$dir/state" --display headless --panel none --frames 1 \
  --width 64 --height 48 --probe camera >"$dir/run.out" 2>&1
rc=$?
set -e
[ "$rc" = 0 ] || fail "weft run --probe camera without its plugin exited $rc: $(tail -3 "$dir/run.out")"
grep -q "light probe camera unavailable: .*install the weft-probe-camera package; showing the bundle's stored lighting" "$dir/run.out" ||
  fail "weft run --probe camera without its plugin did not say what to install: $(cat "$dir/run.out")"
grep -q "first frame after" "$dir/run.out" || fail "weft run --probe camera without its plugin showed no frame: $(cat "$dir/run.out")"
# With the plugin: the camera probe reaches libcamera (here: no camera, so `camera absent`).
cp -a "$dir/weft-probe-camera/." "$dir/weft/"
set +e
"$root/bin/weft" probe --frames 1 >"$dir/probe2.out" 2>&1
set -e
grep -q "camera absent\|^1 " "$dir/probe2.out" || fail "weft probe with its plugin: $(cat "$dir/probe2.out")"
! grep -q "not installed" "$dir/probe2.out" || fail "weft probe did not find the plugin at its installed place: $(cat "$dir/probe2.out")"

echo "packages under $prefix: weft $(wc -l <"$dir/weft.files") files, weft-tools $(wc -l <"$dir/weft-tools.files"), weft-probe-camera $(wc -l <"$dir/weft-probe-camera.files"); kiosk NEEDED: $(grep '/bin/weft:' "$dir/weft.needed" | sed 's/.*: //' | tr '\n' ' ')"
