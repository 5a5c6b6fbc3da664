#include "lighting/fit_error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace weft {

namespace {
using glm::dvec3;

double relative_rmse(std::span<const dvec3> reference, std::span<const dvec3> approx, std::span<const double> weight) {
  double err = 0.0, mean = 0.0, total = 0.0;
  for (size_t i = 0; i < reference.size(); ++i) {
    const dvec3 e = approx[i] - reference[i];
    err += weight[i] * glm::dot(e, e) / 3.0;
    mean += weight[i] * (reference[i].r + reference[i].g + reference[i].b) / 3.0;
    total += weight[i];
  }
  if (!(mean > 0.0)) return err > 0.0 ? INFINITY : 0.0;
  return std::sqrt(err / total) / (mean / total);
}
}  // namespace

EnvMap render_sgs(std::span<const SphericalGaussian> sgs, int width, int height) {
  EnvMap out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) out.at(x, y) = glm::vec3(evaluate(sgs, out.direction(x, y)));
  return out;
}

std::vector<dvec3> fibonacci_sphere(int n) {
  std::vector<dvec3> out;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return out;
}

std::vector<dvec3> irradiance(const EnvMap& map, std::span<const dvec3> normals) {
  std::vector<dvec3> dirs, power;  // Ω L per texel
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      dirs.push_back(map.direction(x, y));
      power.push_back(map.solid_angle(y) * dvec3(map.at(x, y)));
    }
  std::vector<dvec3> out(normals.size(), dvec3(0.0));
  for (size_t n = 0; n < normals.size(); ++n)
    for (size_t i = 0; i < dirs.size(); ++i) out[n] += std::max(0.0, glm::dot(normals[n], dirs[i])) * power[i];
  return out;
}

SgFitError measure_fit_error(const EnvMap& map, std::span<const SphericalGaussian> sgs, const SgFitErrorOptions& options) {
  const EnvMap reference = map.width > 1024 ? resample(map, 1024, 512) : map;
  const EnvMap fitted = render_sgs(sgs, reference.width, reference.height);

  auto radiance_rmse = [](const EnvMap& reference, const EnvMap& fitted) {
    std::vector<dvec3> a, b;
    std::vector<double> w;
    for (int y = 0; y < reference.height; ++y)
      for (int x = 0; x < reference.width; ++x) {
        a.emplace_back(reference.at(x, y));
        b.emplace_back(fitted.at(x, y));
        w.push_back(reference.solid_angle(y));
      }
    return relative_rmse(a, b, w);
  };
  SgFitError out;
  out.radiance_rmse = radiance_rmse(reference, fitted);
  out.radiance_rmse_coarse = radiance_rmse(resample(reference, 64, 32), resample(fitted, 64, 32));
  {
    const int gw = options.irradiance_grid_width, gh = gw / 2;
    const auto normals = fibonacci_sphere(options.normals);
    const auto e_map = irradiance(resample(reference, gw, gh), normals);
    const auto e_fit = irradiance(resample(fitted, gw, gh), normals);
    const std::vector<double> w(normals.size(), 1.0);
    out.irradiance_rmse = relative_rmse(e_map, e_fit, w);
  }
  return out;
}

}  // namespace weft
