#include "image/tone_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace weft {

namespace {
double hable(double x) {
  const FilmicCurve& c = kFilmicCurve;
  const double a = c.shoulder_strength, b = c.linear_strength, cc = c.linear_angle, d = c.toe_strength,
               e = c.toe_numerator, f = c.toe_denominator;
  return (x * (a * x + cc * b) + d * e) / (x * (a * x + b) + d * f) - e / f;
}
}  // namespace

double filmic_curve(double exposed) {
  if (!(exposed > 0.0)) return 0.0;
  return std::clamp(hable(exposed) / hable(kFilmicCurve.white), 0.0, 1.0);
}

double srgb_encode(double linear) {
  const double x = std::clamp(std::isfinite(linear) ? linear : 0.0, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

double display_value(double radiance, double exposure) { return srgb_encode(filmic_curve(exposure * radiance)); }

double luminance(const glm::dvec3& p) { return 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b; }

double log_average_luminance(const std::vector<glm::dvec3>& pixels, const std::vector<bool>& include) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < pixels.size(); ++i) {
    if (!include.empty() && !include[i]) continue;
    const double l = luminance(pixels[i]);
    if (!std::isfinite(l)) continue;
    sum += std::log(std::max(l, kMeteringFloor));
    ++n;
  }
  return n ? std::exp(sum / double(n)) : 0.0;
}

double metered_exposure(double log_average, double bias_ev) {
  const double bias = std::exp2(bias_ev);
  return log_average > 0.0 ? bias * kMeteringKey / log_average : bias;
}

double adapt_exposure(double current, double target, double dt_s, double tau_s) {
  if (!(current > 0.0) || !(tau_s > 0.0)) return target;
  const double k = 1.0 - std::exp(-std::max(dt_s, 0.0) / tau_s);
  return std::exp(std::log(current) + k * (std::log(target) - std::log(current)));
}

std::string tone_map_glsl_defines() {
  const FilmicCurve& c = kFilmicCurve;
  const std::pair<const char*, double> v[] = {{"A", c.shoulder_strength}, {"B", c.linear_strength},
                                              {"C", c.linear_angle},      {"D", c.toe_strength},
                                              {"E", c.toe_numerator},     {"F", c.toe_denominator},
                                              {"W", c.white}};
  std::string out;
  char line[80];
  for (const auto& [name, value] : v) {
    std::snprintf(line, sizeof line, "#define WEFT_FILMIC_%s %.9g\n", name, value);
    out += line;
  }
  return out;
}

}  // namespace weft
