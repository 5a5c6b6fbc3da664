#pragma once
// The close-up a photographer takes after the last turned photo (capture/closeup_shot.h): the
// swatch from straight above, `field_mm` across the frame at a random roll and weave phase, each
// pixel the resolved weave (core/weave_layout.h: the one thread sample that lies there) under the
// map's lights, with the scale tag laid on it, then the same camera as the photos.
#include <cstdint>
#include <vector>

#include "capture/fabric_fit.h"
#include "capture/photo_files.h"
#include "capture/simulated_camera.h"
#include "core/fabric.h"

namespace weft {

struct CloseupSimulationOptions {
  int width = 2400, height = 1800;
  double field_mm = 15.0;      // across the frame's width: a macro lens near 1:2, a phone's macro mode
  // The scale tag (capture_card.h: id 5) on the swatch in a random corner of the frame, its
  // image +x along the warp, lit as paper.
  bool scale_tag = true;
  double turn = 0;             // the swatch's warp angle, radians (the last photo's)
  double exposure_scale = 1;   // linear value per unit radiance at the metered exposure
  int tangent_samples = 32;
  std::uint64_t seed = 1;
};

struct SimulatedCloseup {
  // Exposed in whole stops below the metered exposure until its brightest 0.5 % of pixels sit
  // below 90 % of full scale (a satin float facing a lamp outshines the paper).
  Photo photo;
  glm::dvec3 warp_over_weft{1.0};  // the truth of what the close-up measures: the threads' mean radiances
};

SimulatedCloseup simulate_closeup(const Fabric& fabric, const std::vector<FitLight>& lights, const SimulatedCamera& camera,
                       const CloseupSimulationOptions& options);

}  // namespace weft
