#pragma once
// The display operator every Weft picture goes through (the kiosk's GLSL tone mapper and
// write_png alike): exposure metered on the cloth, an operator bias in EV, Hable's filmic
// curve, sRGB encoding. The curve's constants live here once; the GLSL reads them through
// tone_map_glsl_defines().
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace weft {

// Hable's filmic curve ("Filmic tonemapping for real-time rendering", SIGGRAPH 2010 course;
// the "Uncharted 2" fit): h(x) = (x(Ax+CB)+DE)/(x(Ax+B)+DF) − E/F, shown as h(x)/h(W) so that
// the linear white point W maps to 1; h(0) = 0, increasing, a toe below and a soft shoulder above.
struct FilmicCurve {
  double shoulder_strength = 0.15;  // A
  double linear_strength = 0.50;    // B
  double linear_angle = 0.10;       // C
  double toe_strength = 0.20;       // D
  double toe_numerator = 0.02;      // E
  double toe_denominator = 0.30;    // F
  double white = 11.2;              // W: exposed radiance shown as full white
};
inline constexpr FilmicCurve kFilmicCurve{};

// Metering: the log-average luminance of the cloth's pixels maps to this exposed value, which
// the curve shows as mid grey (h(0.5)/h(W) ≈ 0.17 linear, ≈ 0.45 after sRGB encoding).
inline constexpr double kMeteringKey = 0.5;
// Pixels darker than this (luminance) count as this in the log average, so black pixels
// cannot drive the exposure to infinity.
inline constexpr double kMeteringFloor = 1e-4;

double filmic_curve(double exposed);                 // h(x)/h(W) clamped to [0, 1]; 0 for x ≤ 0 or NaN
double srgb_encode(double linear);                   // IEC 61966-2-1, input clamped to [0, 1]
double display_value(double radiance, double exposure);  // srgb_encode(filmic_curve(exposure·radiance))
double luminance(const glm::dvec3& rgb);             // Rec. 709 weights

// exp(mean(log(max(luminance, floor)))) over the pixels where `include` is true (all when
// empty), ignoring non-finite ones; 0 when none is included.
double log_average_luminance(const std::vector<glm::dvec3>& pixels, const std::vector<bool>& include = {});
// The exposure that takes a log-average luminance to kMeteringKey, times 2^bias_ev; 2^bias_ev
// when nothing was metered (log_average ≤ 0).
double metered_exposure(double log_average, double bias_ev = 0.0);

// Exposure adaptation across frames: moves `current` towards `target` in log space with time
// constant `tau_s` (first-order lag), so a lighting change eases in instead of jumping.
double adapt_exposure(double current, double target, double dt_s, double tau_s);

// "#define WEFT_FILMIC_A ..." lines for the GLSL tone mapper (render/shaders/tonemap.frag).
std::string tone_map_glsl_defines();

}  // namespace weft
