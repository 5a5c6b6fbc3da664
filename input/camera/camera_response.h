#pragma once
// The camera's radiometric response: how linear sensor exposure becomes an 8-bit code value,
// and back. The HDR merge needs the inverse; the mock camera applies the forward curve.
//
// Calibration (what the numbers mean and how to get them for a real camera):
//  * curve: the ISP's tone curve. The default is the sRGB transfer function, which is what a
//    libcamera ISP (e.g. the Raspberry Pi tuning's default gamma) approximates for RGB888
//    output. A measured curve can be given as 256 linear values (`inverse_table`), e.g. from a
//    Debevec–Malik solve over a bracket of a static grey card; it must be increasing.
//  * radiance_scale k: the linear sensor value (1 = full scale) that one unit of scene radiance
//    produces per second of exposure at gain 1 after the ball's reflectance. Measure it once by
//    photographing a source of known radiance (or a grey card under a known illuminance) at a
//    known exposure: k = f⁻¹(z) / (L · t · g). It fixes the absolute scale of the fitted SGs.
//  * ball_reflectance ρ: the chrome ball's specular reflectance (≈ 0.6 for polished chrome,
//    taken as angle-independent): radiance = f⁻¹(z) / (ρ · k · t · g).
#include <array>
#include <cstdint>

namespace weft {

struct CameraResponse {
  // f⁻¹: code value -> linear sensor value in [0, 1].
  std::array<float, 256> inverse_table{};

  // The sRGB transfer curve.
  static CameraResponse srgb();
  // Forward curve for the mock camera: linear [0,1] -> code value (rounded, clipped).
  uint8_t encode(double linear) const;
  double decode(uint8_t code) const { return inverse_table[code]; }
  // True when the table is increasing with f⁻¹(0) ≥ 0 and f⁻¹(255) = 1 (a usable calibration).
  bool valid() const;
};

struct CameraCalibration {
  CameraResponse response = CameraResponse::srgb();
  double radiance_scale = 1.0;   // k, see above
  double ball_reflectance = 0.6; // ρ
};

}  // namespace weft
