#pragma once
// The lighting of a capture, read off the mirror ball in its photos: each photo's ball, merged
// with its darker bracketed exposures where the photo clips the highlights, unwrapped
// (probe/mirror_ball_unwrap.h) in that camera's frame and turned into the card's world frame,
// the photos' maps averaged, scaled so that the card's irradiance at +Z is π (the units the
// response calibration gives the swatch: a white diffuser reads 1, so the ball's reflectance
// and the exposure drop out), then cut into the directional lights the fabric fit sums
// (light_cells.h).
#include <vector>

#include "capture/card_detection.h"
#include "capture/fabric_fit.h"
#include "capture/light_cells.h"
#include "capture/photo_files.h"
#include "capture/response_calibration.h"
#include "lighting/env_map.h"

namespace weft {

struct BallView {
  EnvMap map;                // world frame, the response's relative units (before scaling)
  double clipped_fraction;   // ball pixels with a channel clipped in every exposure
};

// A ball pixel with a code from this up in any channel is clipped (JPEG rings just below 255).
inline constexpr int kBallClipCode = 240;

// One exposure of the ball: the photo itself (ev 0) or one of its brackets (photo_files.h),
// shot from the same pose, read through the photo's response scaled by 2^ev.
struct BallExposure {
  const Photo* photo;
  double ev = 0;
};

// The ball merged from `exposures` (the photo first, all of its size) to high dynamic range, then
// unwrapped into the world frame through the photo's `view`.
BallView read_ball(const std::vector<BallExposure>& exposures, const CardView& view, const ResponseModel& response);

struct CaptureLighting {
  EnvMap map;                    // averaged and scaled
  std::vector<FitLight> lights;  // its cells above the card's horizon
};

CaptureLighting capture_lighting(const std::vector<BallView>& balls, const LightCellOptions& cells = {});

}  // namespace weft
