#pragma once
// The photos' radiometric response, calibrated from the card itself: the six grey patches of
// known reflectance and the white paper all over the card, lit by one irradiance E (the card is
// flat), give, per photo,
//   linear(z, r) = s_c⁻¹ · srgb⁻¹(z/255)^β / (1 − v·r²),   linear = ρ·E/π in the lighting's units,
// a curve β about sRGB (a camera's ISP curve is near it, not on it), the lens's vignetting v
// (r: distance from the image centre over the half diagonal) and a per-channel scale s_c that
// holds exposure, white balance and E. Fitted by a grid over (β, v), refined on a finer grid
// about the best, with s_c solved in closed form, on log values, each sample alike: the darkest
// patch counts as much as a paper cell. The photos of one capture share a camera and lens, so β
// and v are fitted across all of them (the card spans only the image's middle: one photo's paper
// barely shows v), each photo keeping its own s_c (exposure and white balance may change between shots). Samples that
// disagree with the fit by far more than the rest (a shadow, a smudge on the paper) are dropped
// once and the fit repeated.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "camera/camera_response.h"

namespace weft {

struct ResponseModel {
  double beta = 1.0;
  double vignetting = 0.0;
  glm::dvec3 scale{1.0};  // s_c: code-linear value of a white (ρ = 1) diffuser

  // srgb⁻¹(z/255)^β: the sensor's linear value, before vignetting and scale.
  double sensor(std::uint8_t code) const;
  // The reflectance-like value ρ·E/π / (E/π) of a pixel: sensor / ((1 − v·r²)·s_c).
  glm::dvec3 relative(const std::array<std::uint8_t, 3>& code, double r2) const;
  // The curve as a CameraResponse table (the mock camera's forward curve).
  CameraResponse curve() const;
};

// One region of the card that shows a known reflectance: its pixels' code histograms.
struct ResponseSample {
  std::array<std::array<std::uint32_t, 256>, 3> histogram{};
  std::uint32_t count = 0;
  double reflectance = 0;
  double r2 = 0;  // its centre's squared normalised distance from the image centre
  void add(const std::array<std::uint8_t, 3>& code) {
    for (int c = 0; c < 3; ++c) ++histogram[c][code[c]];
    ++count;
  }
};

struct ResponseFit {
  ResponseModel model;
  double rms_log_error = 0;  // over the samples used
  int samples_used = 0;
};

// The samples a fit can use: unclipped and not near black.
int usable_samples(const std::vector<ResponseSample>& samples);

// One photo's fit. Throws std::runtime_error when fewer than four samples are usable.
ResponseFit fit_response(const std::vector<ResponseSample>& samples);

// The photos' fits with β and v shared, in the order of `photos` (each a photo's samples).
// Throws std::runtime_error when a photo has fewer than four usable samples.
std::vector<ResponseFit> fit_shared_response(const std::vector<std::vector<ResponseSample>>& photos);

}  // namespace weft
