#include "reference/thin_quadrature.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;

dvec3 one_sg(const ThinParams& p, const dvec3& n, double mu, const SphericalGaussian& g, int polar,
             const std::function<bool(const dvec3&)>& visible) {
  const dvec3 xi = g.axis;
  const dvec3 t1 = glm::normalize(std::abs(xi.x) < 0.9 ? glm::cross(xi, dvec3(1, 0, 0)) : glm::cross(xi, dvec3(0, 1, 0)));
  const dvec3 t2 = glm::cross(xi, t1);
  const double lambda = g.sharpness;
  const double spread = -std::expm1(-2.0 * lambda);  // 1 − e^{−2λ}
  const int azimuth = 2 * polar;
  dvec3 sum(0.0);
  for (int i = 0; i < polar; ++i) {
    const double s = (i + 0.5) / polar;
    // Inverse CDF of the SG's polar density e^{λ(u−1)} on u ∈ [−1, 1].
    const double u = lambda > 1e-9 ? 1.0 + std::log1p(-s * spread) / lambda : 1.0 - 2.0 * s;
    const double r = std::sqrt(std::max(0.0, 1.0 - u * u));
    for (int k = 0; k < azimuth; ++k) {
      const double phi = 2.0 * kPi * (k + 0.5) / azimuth;
      const dvec3 w = u * xi + r * (std::cos(phi) * t1 + std::sin(phi) * t2);
      const double mu0 = glm::dot(n, w);
      if (visible && !visible(w)) continue;
      if (mu0 > 0.0) sum += mu0 * thin_reflection_kernel(p, mu, mu0);
      else if (mu0 < 0.0) sum += -mu0 * thin_transmission_kernel(p, mu, -mu0);
    }
  }
  return integral(g) * sum / double(polar * azimuth);
}
}  // namespace

ThinQuadratureResult integrate_thin_scatter(const ThinParams& p, const dvec3& n, const dvec3& wo,
                                            std::span<const SphericalGaussian> sgs,
                                            const ThinQuadratureOptions& options) {
  ThinQuadratureResult r;
  const double mu = glm::dot(n, wo);
  if (mu <= 0.0) {
    r.converged = true;
    return r;
  }
  auto at = [&](int polar) {
    dvec3 l(0.0);
    for (const auto& g : sgs) l += one_sg(p, n, mu, g, polar, options.visible);
    return l;
  };
  if (options.fixed_polar > 0) {
    r.radiance = at(options.fixed_polar);
    r.polar_cells = options.fixed_polar;
    return r;
  }
  const double tolerance = options.tolerance;
  dvec3 prev = at(32);
  for (int polar = 64; polar <= 1024; polar *= 2) {
    const dvec3 cur = at(polar);
    const double scale = std::max({std::abs(cur.r), std::abs(cur.g), std::abs(cur.b), 1e-300});
    const dvec3 d = glm::abs(cur - prev);
    r.radiance = cur;
    r.polar_cells = polar;
    if (std::max({d.r, d.g, d.b}) <= tolerance * scale) {
      r.converged = true;
      return r;
    }
    prev = cur;
  }
  return r;
}

}  // namespace weft
