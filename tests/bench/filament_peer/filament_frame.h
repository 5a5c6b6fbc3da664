#pragma once
// Frames of a Weft scene drawn by Filament 1.9 (Debian's libfilament, OpenGL backend over GLX):
// the scene's own triangles (the meshes Weft and its reference draw, so the comparison is of
// shading alone), cloth in peer_cloth.mat, floors and occluders in peer_lambert.mat, lit by an
// IBL from cmgen (filament_environment.h), no shadows, seen from the scene's camera.
//
// Two ways to draw:
//  - linear(): what is measured. Post-processing off (no tone mapping, anti-aliasing or
//    dithering), the camera's exposure set to 1 (Camera::setExposure(1): aperture 1, shutter
//    1.2 s, ISO 100), the IBL's intensity 1, into an RGBA32F target: each pixel is the
//    radiance in the map's units, as Weft's rungs and the reference give it. Timed as Weft's
//    bench times its rungs (frame_render.h): the median over the timed frames after a warm-up,
//    Engine::flushAndWait (which ends in glFinish) included, the readback not.
//  - shipping_ms(): the frame a Filament showroom shows: Filament's defaults (its tone mapper,
//    FXAA, dithering) into its 8-bit headless swap chain, timed the same way.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench/filament_peer/filament_cloth.h"
#include "image/image.h"
#include "scene/scene.h"

namespace weft::peer {

// Why Filament cannot draw here (its GLX backend needs an X display: none is reachable from
// $DISPLAY), or "" when it can. Filament itself exits the process without one, so ask first.
std::string filament_unavailable();

struct FilamentFrame {
  Image image;             // linear radiance, row 0 at the top
  double median_ms = 0.0;  // over `frames` timed frames
  int frames = 0;
};

class FilamentPeer {
public:
  // Starts Filament (its engine, the embedded materials). Call filament_unavailable() first.
  FilamentPeer();
  ~FilamentPeer();
  FilamentPeer(const FilamentPeer&) = delete;
  FilamentPeer& operator=(const FilamentPeer&) = delete;

  // The scene's objects; `cloth` gives each cloth object's material, in Scene::cloth_objects order.
  // Throws std::invalid_argument when the counts differ.
  void set_scene(const Scene& scene, const std::vector<FilamentCloth>& cloth);
  // The IBL from a cmgen KTX (prefiltered cubemap, SH in its metadata). Throws std::runtime_error
  // naming the file when it cannot be read or holds no SH.
  void set_ibl(const std::filesystem::path& ktx);

  FilamentFrame linear(const Camera& camera, int width, int height, int timed_frames);
  double shipping_ms(const Camera& camera, int width, int height, int timed_frames);

private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace weft::peer
