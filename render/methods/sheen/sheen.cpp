#include "methods/sheen/sheen.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/fresnel.h"
#include "methods/sg_lights.h"

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;
// Filament's floor on sin²θ_h: keeps pow() away from 0 at the lobe's zero.
constexpr double kMinSin2 = 0.0078125;
}  // namespace

SheenParams sheen_params(const Fabric& fabric) {
  const double a0 = fabric.threads[0].coverage, a1 = fabric.threads[1].coverage;
  const double total = a0 + a1;
  SheenParams p;
  p.diffuse = dvec3(0.0);
  p.sheen_colour = dvec3(0.0);
  double sigma = 0.0;
  for (int j = 0; j < 2; ++j) {
    const ThreadParams& t = fabric.threads[j];
    const double w = total > 0.0 ? t.coverage / total : 0.5;
    p.thread_diffuse[j] = w * t.albedo;
    p.diffuse += p.thread_diffuse[j];
    p.sheen_colour += dvec3(w * fresnel_dielectric(t.eta, 1.0));
    sigma += w * t.gamma_s;
  }
  p.roughness = std::clamp(sigma * sigma, 0.01, 1.0);
  return p;
}

SheenParams sheen_tinted(SheenParams p, const std::array<dvec3, 2>& tint) {
  for (int j = 0; j < 2; ++j) p.thread_diffuse[j] *= tint[j];
  p.diffuse = p.thread_diffuse[0] + p.thread_diffuse[1];
  return p;
}

double charlie_distribution(double alpha, double n_dot_h) {
  const double inv = 1.0 / alpha;
  const double sin2 = std::max(1.0 - n_dot_h * n_dot_h, kMinSin2);
  return (2.0 + inv) * std::pow(sin2, 0.5 * inv) / (2.0 * kPi);
}

double neubelt_visibility(double n_dot_l, double n_dot_v) {
  return 1.0 / (4.0 * (n_dot_l + n_dot_v - n_dot_l * n_dot_v));
}

dvec3 sheen_brdf(const SheenParams& p, const dvec3& n, const dvec3& wi, const dvec3& wo) {
  const double nl = glm::dot(n, wi), nv = glm::dot(n, wo);
  if (nl <= 0.0 || nv <= 0.0) return dvec3(0.0);
  const dvec3 h = glm::normalize(wi + wo);
  const double nh = std::clamp(glm::dot(n, h), 0.0, 1.0);
  return p.diffuse / kPi + p.sheen_colour * (charlie_distribution(p.roughness, nh) * neubelt_visibility(nl, nv));
}

dvec3 sheen_radiance(const SheenParams& p, const dvec3& n, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
  if (glm::dot(n, wo) <= 0.0) return dvec3(0.0);
  dvec3 l(0.0);
  for (const auto& g : sgs) l += irradiance(g, n) * sheen_brdf(p, n, lift_above_horizon(g.axis, n), wo);
  return l;
}

}  // namespace weft
