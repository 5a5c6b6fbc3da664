#pragma once
// Photos of a known fabric on the capture card, for testing `weft capture` end to end: N photos
// from a hand-held camera at slightly different poses, the swatch turned by 180°·i/N in photo i,
// everything lit by one environment map (docs/design.md §3, +Z up from the card):
//  - the swatch: the canonical model (docs/design.md §2, fabric level, unoccluded) under the map's
//    directional samples (reference/environment_samples.h), on a grid of view points across it;
//  - the card, the marker and the table: Lambertian under the map's irradiance at +Z;
//  - the mirror ball: drawn by the mock probe camera (probe/mock_probe_source.h) in the map turned
//    into that camera's frame;
//  - then the camera: vignetting, sensor noise, a response curve about sRGB, white balance, JPEG;
//  - closeup.jpg: the swatch from straight above after the last photo, its threads resolved;
//  - while the ball's highlights clip, the same photo 3, 6, … stops darker (photo_files.h's
//    brackets), as a photographer brackets the exposure.
// It writes only what a real capture has: the photos, their brackets and capture.json. The truth
// goes to its own file when asked.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>

#include <vector>

#include "capture/fabric_fit.h"
#include "core/cloth_bsdf.h"
#include "core/fabric.h"
#include "lighting/env_map.h"

namespace weft {

struct CaptureSimulationOptions {
  int photos = 4;
  std::uint64_t seed = 1;
  int width = 1024, height = 768;
  int tangent_samples = 32;    // N_j per thread (docs/design.md §2: ≥ 32 for ground truth)
  int light_cells = 64;        // the map's directional samples: light_cells × light_cells/2
  bool record_focal = true;    // capture.json carries the focal length (a camera's EXIF)
  bool bracket_ball = true;    // darker exposures beside each photo while the ball clips
  // A camera's finest JPEG, as the capture procedure asks (docs/capture.md: at 90 a sparse
  // thread's colour error doubles, from the ball's few lamp pixels).
  int jpeg_quality = 95;
  // closeup.jpg beside the photos (capture/closeup_simulation.h): the threads resolved.
  bool closeup = true;
  std::function<void(double)> progress;
};

// The map as the simulated swatch sees it: its directional samples (light_cells × light_cells/2
// cells) above the card's horizon.
std::vector<FitLight> simulated_swatch_lights(const EnvMap& map, int light_cells);

// The simulated swatch's radiance toward `wo` (unit, world) at one point: the model bound to the
// swatch's frame under those lights. The photos' swatch pixels are drawn from this.
glm::dvec3 simulated_swatch_radiance(ClothBsdf::Point& point, const std::vector<FitLight>& lights, const glm::dvec3& wo);

// Writes DIR/photo_<i>.jpg, its brackets and DIR/capture.json (DIR is created); the truth (fabric, turns,
// cameras, response) as JSON to `truth_out` when given.
void simulate_capture(const Fabric& fabric, const EnvMap& map, const CaptureSimulationOptions& options,
                      const std::filesystem::path& dir, const std::optional<std::filesystem::path>& truth_out = {});

}  // namespace weft
