#include "methods/iwasaki/iwasaki_visibility.h"

#include <algorithm>
#include <cmath>

namespace weft {

SdfSample sdf_in_sample_frame(const SgVisibility& vis, int sg, const SurfaceFrame& f, const std::array<uint32_t, 3>& corners,
                              const dvec3& bary, const ThreadFrame& s, double theta, double phi) {
  const auto [w, dw_dtheta, dw_dphi] = fiber_direction(s, theta, phi);
  const double wn = glm::dot(w, f.n), wv = glm::dot(w, f.v);
  const double cos2 = std::max(wn * wn + wv * wv, 1e-8);  // cos²θ'
  dvec3 g(0.0);
  for (int k = 0; k < 3; ++k) g += bary[k] * vis.at(corners[k], sg);
  // Chain rule through ω (header comment, step 3).
  const dvec3 dtheta_v = f.u / std::sqrt(cos2);
  const dvec3 dphi_v = (wn * f.v - wv * f.n) / cos2;
  SdfSample out;
  out.d = g.x;
  out.d_dtheta = g.y * glm::dot(dtheta_v, dw_dtheta) + g.z * glm::dot(dphi_v, dw_dtheta);
  out.d_dphi = g.y * glm::dot(dtheta_v, dw_dphi) + g.z * glm::dot(dphi_v, dw_dphi);
  return out;
}

}  // namespace weft
