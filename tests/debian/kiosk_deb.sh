#!/usr/bin/env bash
# The kiosk's package, weft_VERSION_ARCH.deb, from a build tree without cpack (which would first
# build every target of the tree, tests included): the install component `weft` with the /usr
# prefix and stripped, as CPack packages it, the maintainer scripts of debian/debian and the
# conffiles list, put together by dpkg-deb. Its Depends are left out: the tests that install it
# say which dependencies they provide. Prints the .deb's path.
# Usage: kiosk_deb.sh BUILD_DIR OUT_DIR
set -euo pipefail
build=$(readlink -f "$1") out=$2
repo=$(cd "$(dirname "$0")/../.." && pwd)
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/DEBIAN" "$out"
DESTDIR="$stage" cmake --install "$build" --prefix /usr --strip --component weft >"$out/install.log" 2>&1 || {
  echo "kiosk_deb: cmake --install $build failed (cmake --build $build first): $(tail -3 "$out/install.log")" >&2
  exit 1
}
cpack_value() { sed -n "s/^set($1 \"\(.*\)\")$/\1/p" "$build/CPackConfig.cmake"; }
version="$(cpack_value CPACK_PACKAGE_VERSION)-$(cpack_value CPACK_DEBIAN_PACKAGE_RELEASE)"
arch=$(dpkg --print-architecture)
cat >"$stage/DEBIAN/control" <<CONTROL
Package: weft
Version: $version
Architecture: $arch
Maintainer: $(cpack_value CPACK_PACKAGE_CONTACT)
Description: cloth rendering showroom kiosk
CONTROL
install -m 0755 "$repo/debian/debian/postinst" "$repo/debian/debian/prerm" "$repo/debian/debian/postrm" "$stage/DEBIAN/"
install -m 0644 "$build/debian/debian/conffiles" "$stage/DEBIAN/"
deb="$out/weft_${version}_${arch}.deb"
dpkg-deb --root-owner-group -b "$stage" "$deb" >"$out/dpkg-deb.log" 2>&1 || {
  echo "kiosk_deb: dpkg-deb -b failed: $(tail -3 "$out/dpkg-deb.log")" >&2
  exit 1
}
echo "$deb"
