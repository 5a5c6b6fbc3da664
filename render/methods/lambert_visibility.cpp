#include "methods/lambert_visibility.h"

#include <algorithm>
#include <cmath>

#include "core/circular_gaussian.h"
#include "methods/iwasaki/iwasaki.h"

namespace weft {

namespace {
constexpr double kCosineSharpness = 2.133;  // max(n·ω, 0) ≈ 1.17·exp(2.133(n·ω − 1))

double bounded_sigma_prime(double sigma, double theta) {
  return sigma / std::max(std::cos(theta), 1e-3);  // σ' of Eq. 11 at the peak, finite at the poles
}
}  // namespace

double lambert_visible_share(const SphericalGaussian& g, const SurfaceFrame& frame, const dvec3& sdf_at_axis,
                             const SigmoidGainTable* kappa) {
  const ThreadFrame vertex_frame = thread_frame(frame, 0, 0.0);  // (t, n', b) = (u, n, v): the SDF's angles
  const SgCircularSplit axis = split_sg(g, vertex_frame);
  SphericalGaussian lobe = g;  // G · cos as one SG
  const dvec3 m = g.sharpness * glm::normalize(g.axis) + kCosineSharpness * frame.n;
  lobe.sharpness = glm::length(m);
  if (!(lobe.sharpness > 1e-9)) return 1.0;  // a lobe opposite the normal: nothing to shade
  lobe.axis = m / lobe.sharpness;
  const SgCircularSplit peak = split_sg(lobe, vertex_frame);
  const double sp = bounded_sigma_prime(peak.sigma_k, peak.theta_k);
  // The SDF, linear in (θ', φ') around the SG axis (Eq. 12's V'), at the lobe's peak.
  const double d = sdf_at_axis.x + sdf_at_axis.y * (peak.theta_k - axis.theta_k) +
                   sdf_at_axis.z * wrap_angle(peak.phi_k - axis.phi_k);
  const double h_sdf = kappa ? kappa->h(peak.sigma_k, sp, d, sdf_at_axis.y, sdf_at_axis.z)
                             : linear_visibility_ratio(peak.sigma_k, sp, d, sdf_at_axis.y, sdf_at_axis.z);
  const double h_horizon = horizon_ratio(vertex_frame, frame.n, peak.theta_k, peak.phi_k, peak.sigma_k, sp);
  if (!(h_horizon > 1e-6)) return 1.0;  // the whole lobe under the surface: the cosine already cut it
  return std::clamp(h_sdf / h_horizon, 0.0, 1.0);
}

dvec3 lambert_irradiance(std::span<const SphericalGaussian> sgs, const SurfaceFrame& frame,
                         const SgVisibility* visibility, size_t vertex, const SigmoidGainTable* kappa) {
  dvec3 e(0.0);
  for (size_t k = 0; k < sgs.size(); ++k) {
    const dvec3 open = irradiance(sgs[k], frame.n);
    if (!visibility) {
      e += open;
      continue;
    }
    e += open * lambert_visible_share(sgs[k], frame, visibility->at(vertex, int(k)), kappa);
  }
  return e;
}

}  // namespace weft
