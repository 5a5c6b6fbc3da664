#include "methods/thin/thin.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "methods/sg_lights.h"
#include "methods/sgpoint/sgpoint.h"

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kMinMu = 1e-4;
// Below this |μ − μ₀| K_t takes its derivative form at the midpoint (error O(δ²)): the
// difference quotient would cancel.
constexpr double kCoincident = 1e-3;
}  // namespace

ThinParams thin_params(const Fabric& fabric) {
  const double total = fabric.threads[0].coverage + fabric.threads[1].coverage;
  dvec3 c(0.0);
  for (const auto& t : fabric.threads) c += (total > 0.0 ? t.coverage / total : 0.5) * t.albedo;
  const double m = std::max({c.r, c.g, c.b});
  ThinParams p;
  p.tau = fabric.optical_thickness > 0.0 ? fabric.optical_thickness : kDefaultThinTau;
  p.albedo = m > 0.0 ? 0.8 * c / m : dvec3(0.8);
  return p;
}

double thin_alpha(const ThinParams& p, double mu) { return std::exp(-p.tau / std::max(mu, kMinMu)); }

dvec3 thin_reflection_kernel(const ThinParams& p, double mu, double mu0) {
  mu = std::max(mu, kMinMu), mu0 = std::max(mu0, kMinMu);
  return p.albedo / (4.0 * kPi) * (-std::expm1(-p.tau * (1.0 / mu + 1.0 / mu0)) / (mu + mu0));
}

dvec3 thin_transmission_kernel(const ThinParams& p, double mu, double mu0) {
  mu = std::max(mu, kMinMu), mu0 = std::max(mu0, kMinMu);
  double k;
  if (std::abs(mu - mu0) < kCoincident) {
    const double m = 0.5 * (mu + mu0);
    k = p.tau / (m * m) * std::exp(-p.tau / m);
  } else {
    k = (std::exp(-p.tau / mu) - std::exp(-p.tau / mu0)) / (mu - mu0);
  }
  return p.albedo / (4.0 * kPi) * k;
}

dvec3 thin_scatter(const ThinParams& p, const dvec3& n, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                   std::span<const ThinSideVisibility> visibility) {
  if (!visibility.empty() && visibility.size() != sgs.size())
    throw std::invalid_argument("thin_scatter: one visibility per SG");
  const double mu = glm::dot(n, wo);
  if (mu <= 0.0) return dvec3(0.0);
  dvec3 l(0.0);
  for (size_t k = 0; k < sgs.size(); ++k) {
    const SphericalGaussian& g = sgs[k];
    const ThinSideVisibility v = visibility.empty() ? ThinSideVisibility{} : visibility[k];
    const double c = glm::dot(g.axis, n);
    const double mu_front = sg_effective_cosine(g.sharpness, c), mu_back = sg_effective_cosine(g.sharpness, -c);
    l += v.front * irradiance(g, n) * thin_reflection_kernel(p, mu, mu_front);
    l += v.back * irradiance(g, -n) * thin_transmission_kernel(p, mu, mu_back);
  }
  return l;
}

ThinShade thin_radiance(const ClothBsdf& bsdf, const ThinParams& p, SurfaceFrame frame, const dvec3& wo,
                        std::span<const SphericalGaussian> sgs) {
  if (glm::dot(frame.n, wo) < 0.0) {  // the side facing the viewer, as sgpoint.frag does
    frame.n = -frame.n;
    frame.v = glm::cross(frame.n, frame.u);
  }
  return thin_compose(p, frame.n, wo, sgs, sgpoint_radiance(bsdf, frame, wo, sgs));
}

ThinShade thin_compose(const ThinParams& p, const dvec3& n, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                       const dvec3& reflection, std::span<const ThinSideVisibility> visibility) {
  ThinShade s;
  s.alpha = thin_alpha(p, glm::dot(n, wo));
  s.source = (1.0 - s.alpha) * reflection + thin_scatter(p, n, wo, sgs, visibility);
  return s;
}

}  // namespace weft
