#!/usr/bin/env bash
# Weft's one set-up script: installs the Debian 12 packages the project needs (only what is
# missing; quiet when all is there), builds, and then runs or tests.
#   ./setup.sh run    install, build, render the default showroom scene
#   ./setup.sh test   install, build, run the test suite (what .ci/run does)
#   ./setup.sh package  install, build, make the Debian packages, check them with lintian
#   ./setup.sh deps | build
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(
  build-essential cmake pkg-config git
  lld  # links the ~200 executables in a third of GNU ld's time (CMakeLists.txt)
  libeigen3-dev libglm-dev nlohmann-json3-dev libcli11-dev
  libembree-dev libtbb-dev libopenexr-dev libimath-dev libpng-dev libtinygltf-dev
  libjpeg62-turbo-dev  # JPEG textures in glTF files (render/image/texture_image.h), the capture photos
  libapriltag-dev  # the capture card's markers (render/capture/card_detection.h)
  liblcms2-dev  # CIEDE2000 for fitted thread colours (render/capture/colour_difference.h)
  libfftw3-dev  # the close-up's 2-D spectrum: ends and picks per cm (render/capture/thread_counts.h)
  libdraco-dev libmeshoptimizer-dev  # compressed glTF meshes: Draco and meshopt (render/scene/gltf_draco.h, gltf_meshopt.h)
  libegl-dev libgles-dev libgbm-dev libdrm-dev libegl-mesa0 libgl1-mesa-dri
  libhidapi-dev libgpiod-dev libcamera-dev libsystemd-dev systemd
  libudev-dev  # the kiosk follows displays being plugged (render/kiosk/display_watch.h)
  libharfbuzz-dev libfreetype-dev fonts-dejavu-core  # the kiosk's label (render/label)
  libgtest-dev libgmock-dev
  help2man dpkg-dev file  # weft(1) from --help; the packages' Depends (dpkg-shlibdeps, cpack)
  lintian  # checks the packages (./setup.sh package)
  assimp-testmodels  # real glTF 2.0 files for the importer tests (tests/scene)
  clang libclang-rt-14-dev  # libFuzzer targets (tests/fuzz)
  qemu-system-x86 busybox-static kmod cpio dbus-daemon  # the kiosk VM test (tests/kiosk/KIOSK_VM.md)
  libfilament-dev libfilament-tools libx11-dev xvfb  # the peer bench: Filament on the same scenes (tests/bench/filament_peer)
)
BUILD_DIR=${WEFT_BUILD_DIR:-build}

deps() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "setup: installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

build() {
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  cmake --build "$BUILD_DIR" -j"$(nproc)"
}

run_default() {
  # The default showroom: an armchair in linen with satin cushions (assets/scenes/armchair.gltf),
  # baked once into a bundle, then shown fullscreen on the first connected display (DRM/KMS), or
  # rendered headless to an image when there is none.
  local weft="$BUILD_DIR/render/app/weft" bundle="$BUILD_DIR/showroom.weft" state="$BUILD_DIR/kiosk-state"
  local scene=assets/scenes/showroom.json
  # Re-baked after every rebuild of weft or edit of the scene, so the bundle matches both.
  { [ "$bundle" -nt "$weft" ] && [ "$bundle" -nt "$scene" ] && [ "$bundle" -nt assets/scenes/armchair.gltf ]; } ||
    "$weft" bake --scene "$scene" --table-grid 32 --sdf-resolution 64 --floor-sdf-resolution 32 \
      --out "$bundle"  # the default settings, coarser grids: a few minutes of CPU (docs/showroom/README.md)
  mkdir -p "$state"
  # The close-up beside it: the kiosk's zoom all the way in (the scene's closeup_camera), where the
  # weave layer shows the linen's plain weave and the satin's floats.
  "$weft" run --bundle "$bundle" --state-dir "$state" --display headless --panel none --frames 1 --zoom 1 \
    --turntable 0 --screenshot "$BUILD_DIR/showroom-closeup.png"
  echo "setup: wrote $BUILD_DIR/showroom-closeup.png (the close-up: keys t/g zoom on the kiosk)"
  # The satin's floats need a macro view: its 60 ends/cm are under a pixel beyond ~10 cm at
  # 640x480, so a camera 7 cm from the back cushion, the kiosk's rung with the weave layer.
  "$weft" render --bundle "$bundle" --method iwasaki_vertex_quadrature --weave --width 640 --height 480 --frames 1 \
    --camera 0.05,0.06,0.735:0.05,0.125,0.72:30 --out "$BUILD_DIR/showroom-satin.exr" >/dev/null
  echo "setup: wrote $BUILD_DIR/showroom-satin.png (the satin cushion at 7 cm)"
  local panel=none
  [ -t 0 ] && panel=keyboard  # turn the knobs from this terminal (weft run --help; input/panel/KNOBS.md)
  if "$weft" run --bundle "$bundle" --state-dir "$state" --display kms --panel "$panel"; then
    return 0
  fi
  echo "setup: no display to take over; rendering the showroom headless instead"
  "$weft" run --bundle "$bundle" --state-dir "$state" --display headless --panel none --frames 1 \
    --screenshot "$BUILD_DIR/showroom.png"
  echo "setup: wrote $BUILD_DIR/showroom.png"
}

package() {
  # The install rules of a /usr build, packaged by CPack into weft, weft-tools and
  # weft-probe-camera (debian/CMakeLists.txt says why not dpkg-buildpackage, and what each holds).
  # Only the prefix differs from `build`: only what holds an install path is rebuilt.
  cmake -S . -B "$BUILD_DIR" -DCMAKE_INSTALL_PREFIX=/usr >/dev/null
  cmake --build "$BUILD_DIR" -j"$(nproc)"
  (cd "$BUILD_DIR" && cpack -G DEB >/dev/null)
  local version arch debs=()
  version=$(sed -n '1s/^weft (\([^)]*\)).*/\1/p' debian/changelog)
  arch=$(dpkg --print-architecture)
  for p in weft weft-tools weft-probe-camera; do debs+=("$BUILD_DIR/${p}_${version}_${arch}.deb"); done
  # Debian's checks on the packages: an error fails the command, warnings are shown
  # (debian/lintian-overrides holds those that stand, each with its reason).
  lintian --fail-on error --info "${debs[@]}"
  printf 'setup: wrote %s\n' "${debs[@]}"
}

test_all() {
  # Benchmarks and long bakes carry the label `bench` and stay out of this run.
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$(nproc)" -LE bench
}

case "${1:-}" in
  deps) deps ;;
  build) deps; build ;;
  run) deps; build; run_default ;;
  test) deps; build; test_all ;;
  package) deps; package ;;
  *) sed -n '2,9p' "$0"; exit 2 ;;
esac
