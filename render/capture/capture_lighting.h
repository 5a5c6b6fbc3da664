#pragma once
// The lighting of a capture, read off the mirror ball in its photos: each photo's ball unwrapped
// (probe/mirror_ball_unwrap.h) in that camera's frame and turned into the card's world frame,
// the photos' maps averaged, scaled so that the card's irradiance at +Z is π (the units the
// response calibration gives the swatch: a white diffuser reads 1, so the ball's reflectance
// and the exposure drop out), then fitted with SGs (lighting/sg_fit.h) and cut into the
// directional lights the fabric fit sums.
#include <vector>

#include "capture/card_detection.h"
#include "capture/fabric_fit.h"
#include "capture/photo_files.h"
#include "capture/response_calibration.h"
#include "core/spherical_gaussian.h"
#include "lighting/env_map.h"

namespace weft {

struct BallView {
  EnvMap map;                // world frame, the response's relative units (before scaling)
  double clipped_fraction;   // ball pixels with a clipped channel
};

BallView read_ball(const Photo& photo, const CardView& view, const ResponseModel& response);

struct CaptureLighting {
  EnvMap map;      // averaged and scaled
  SgLighting sgs;  // fitted to it, scaled to the same irradiance
  std::vector<FitLight> lights;  // the SGs above the card's horizon
};

CaptureLighting capture_lighting(const std::vector<BallView>& balls, int sg_count = 10);

}  // namespace weft
