#pragma once
// The camera that `weft capture --simulate` stands in for: a response curve about sRGB, the lens's
// vignetting, a white balance, shot and read noise, JPEG at full colour resolution.
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include <glm/glm.hpp>

#include "capture/response_calibration.h"
#include "image/jpeg_encode.h"

namespace weft {

// The simulated photographer's exposure: whole stops below the metered one until `peak` (exposed,
// white-balanced linear value) sits under 90 % of full scale.
inline int stops_to_fit(double peak) { return peak > 0.9 ? static_cast<int>(std::ceil(std::log2(peak / 0.9))) : 0; }

struct SimulatedCamera {
  ResponseModel response{1.12, 0.10, glm::dvec3(1.0)};
  glm::dvec3 white_balance{1.04, 1.0, 0.93};
  double shot_noise = 1.0 / 3000.0;  // variance per unit linear value
  double read_noise = 0.002;
  // Full colour resolution: halved, it tints a lamp a few pixels wide on the ball toward grey
  // (docs/capture.md asks for a camera's 4:4:4 setting or PNG).
  JpegChroma jpeg_chroma = JpegChroma::full;

  // A pixel's codes from its exposed linear value at squared image radius r2 (card_samples.h's
  // image_radius2): white balance, vignetting, noise, then the curve.
  std::array<std::uint8_t, 3> develop(glm::dvec3 linear, double r2, const CameraResponse& curve, std::mt19937_64& rng,
                                      std::normal_distribution<double>& unit) const {
    linear *= white_balance * (1.0 - response.vignetting * r2);
    std::array<std::uint8_t, 3> code{};
    for (int c = 0; c < 3; ++c) {
      const double sigma = std::sqrt(std::max(linear[c], 0.0) * shot_noise + read_noise * read_noise);
      code[c] = curve.encode(linear[c] + sigma * unit(rng));
    }
    return code;
  }
};

}  // namespace weft
