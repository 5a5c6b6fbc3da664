#!/usr/bin/env bash
# Packs what tests/gpu/gpu_bench.sh and gpu_check.sh need on a GPU machine that has none of the
# project's Debian libraries (the device machine: another distribution, its own GL driver): the
# build's weft, weft-offline and kiosk_frame_bench and the parity tests, stripped; the Debian
# libraries `ldd` lists for them (not libc, libm or the GL/EGL loaders, which the machine's driver
# brings); and the two bundles.
#
#   tests/gpu/gpu_pack.sh BUILD_DIR BUNDLE_DIR OUT.tar.xz
#
# On the GPU machine: unpack, drop the libraries its system already has (`ldconfig -p`), set
# LD_LIBRARY_PATH to pkg/lib, and run tests/gpu/gpu_bench.sh pkg/bin pkg/bundles OUT and
# tests/gpu/gpu_check.sh pkg/tests OUT (the tests read assets/ and bake with weft at the paths of
# the build they came from: link those paths to the checkout and to pkg/bin, whose weft runs
# weft-offline beside it for `weft bake`).
set -euo pipefail
if [ $# -lt 3 ] || [ "${1:-}" = "--help" ]; then sed -n '2,14p' "$0"; exit 2; fi
BUILD=$(realpath "$1") BUNDLES=$(realpath "$2") OUT=$3
for b in showroom pillow; do [ -f "$BUNDLES/$b.weft" ] || { echo "no $BUNDLES/$b.weft" >&2; exit 1; }; done
P=$(mktemp -d)
trap 'rm -rf "$P"' EXIT
mkdir -p "$P/pkg/bin" "$P/pkg/lib" "$P/pkg/bundles" "$P/pkg/tests"
for b in render/app/weft render/app/weft-offline tests/bench/kiosk_frame_bench; do strip -o "$P/pkg/bin/$(basename $b)" "$BUILD/$b"; done
for t in gpu_context_test microcylinder_parity_test method_parity_test iwasaki_parity_test vertex_facet_test \
  visible_vertices_test weave_parity_test vertex_normal_map_parity_test sheer_parity_test tone_map_parity_test \
  uniform_budget_test weave_culling_test; do
  [ -x "$BUILD/tests/gpu/$t" ] && strip -o "$P/pkg/tests/$t" "$BUILD/tests/gpu/$t"
done
for f in "$P"/pkg/bin/* "$P"/pkg/tests/*; do ldd "$f"; done | awk '/=>/ {print $3}' | sort -u |
  grep -v -E 'libc\.so|libm\.so|libGL|libEGL|ld-linux|libpthread|libdl\.so|librt\.so' |
  while read -r l; do cp -L "$l" "$P/pkg/lib/"; done
cp "$BUNDLES/showroom.weft" "$BUNDLES/pillow.weft" "$P/pkg/bundles/"
tar -C "$P" -cf - pkg | xz -T2 -6 >"$OUT"
ls -l "$OUT"
