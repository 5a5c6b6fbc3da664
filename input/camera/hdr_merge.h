#pragma once
// Bracketed 8-bit frames -> one linear HDR radiance image (the scene radiance the ball
// reflects, in the units of the SG amplitudes), with the camera's calibration
// (camera_response.h): L = Σ_i f⁻¹(z_i) / (ρ·k·Σ_i t_i·g_i) over the frames where the pixel is
// not clipped (z < 250): the exposure-weighted mean, optimal under shot noise and unbiased for
// dim pixels (no low-code cut-off).
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "camera/camera_response.h"
#include "camera/light_probe_source.h"
#include "camera/mirror_ball.h"

namespace weft {

struct HdrImage {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> radiance;  // row-major, top row first

  const glm::vec3& at(int x, int y) const { return radiance[static_cast<size_t>(y) * width + x]; }
  // Bilinear at continuous image coordinates (pixel centres at +0.5), clamped to the image.
  glm::vec3 sample(double x, double y) const;
};

// What the merge saw on the ball, to reject unusable brackets and to steer the exposure.
struct BracketStats {
  double black_fraction = 0;      // ball pixels dark (code ≤ 2 in every channel) in the longest frame
  double saturated_fraction = 0;  // ball pixels clipped (code ≥ 250 in any channel) in the shortest
  double peak_sensor = 0;         // brightest linear sensor value on the ball in the shortest frame
};

// Merges a bracket (any order, at least one frame, all the same size). Only the ball's
// bounding box is merged (other pixels are 0). Throws ProbeError(bad_frame) on mismatched sizes,
// or when the bracket is black (black_fraction > 0.98: lens cap, lights off, dead sensor) or
// saturated (saturated_fraction > 0.5 in the shortest frame). `stats` is filled before either.
HdrImage merge_bracket(std::span<const ProbeFrame> bracket, const CameraCalibration& calibration,
                       const MirrorBall& ball, BracketStats* stats = nullptr);

}  // namespace weft
