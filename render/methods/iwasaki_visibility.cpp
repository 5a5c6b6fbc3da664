#include "methods/iwasaki_visibility.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bake/visibility_sdf.h"

namespace weft {

VertexSdfGrids VertexSdfGrids::expand(const ObjectVisibility& o) {
  VertexSdfGrids g;
  g.resolution = o.resolution;
  g.vertices = o.vertex_count();
  const int n = o.resolution, cells = n * n;
  const double h = std::numbers::pi / n;
  g.texels.resize(g.vertices * cells * 4);
  DistanceGrid d{n, n, std::vector<double>(cells)};
  for (size_t v = 0; v < g.vertices; ++v) {
    for (int k = 0; k < cells; ++k) {
      double x = o.mean[k];
      for (int t = 0; t < o.terms; ++t) x += double(o.basis[size_t(t) * cells + k]) * o.coefficients[v * o.terms + t];
      d.values[k] = x;
    }
    const SdfGradient grad = sdf_gradient(d, h, /*periodic_cols=*/false);
    float* out = &g.texels[v * cells * 4];
    for (int k = 0; k < cells; ++k) {
      out[4 * k + 0] = float(d.values[k]);
      out[4 * k + 1] = float(grad.d_theta.values[k]);
      out[4 * k + 2] = float(grad.d_phi.values[k]);
      out[4 * k + 3] = 0.0f;
    }
  }
  return g;
}

dvec3 VertexSdfGrids::bilinear(size_t vertex, double gi, double gj) const {
  const int n = resolution;
  const int i0 = std::min(int(gi), n - 2), j0 = std::min(int(gj), n - 2);
  const double fi = gi - i0, fj = gj - j0;
  const float* base = &texels[vertex * size_t(n) * n * 4];
  auto at = [&](int i, int j) {
    const float* p = base + (size_t(i) * n + j) * 4;
    return dvec3(p[0], p[1], p[2]);
  };
  return (1 - fi) * ((1 - fj) * at(i0, j0) + fj * at(i0, j0 + 1)) + fi * ((1 - fj) * at(i0 + 1, j0) + fj * at(i0 + 1, j0 + 1));
}

SdfSample sdf_in_sample_frame(const VertexSdfGrids& grids, const SurfaceFrame& f, const std::array<uint32_t, 3>& corners,
                              const dvec3& bary, const ThreadFrame& s, double theta, double phi) {
  constexpr double kHalfPi = std::numbers::pi / 2;
  const double ct = std::cos(theta), st = std::sin(theta), cp = std::cos(phi), sp = std::sin(phi);
  const dvec3 radial = cp * s.n_prime + sp * s.b;
  const dvec3 w = st * s.t + ct * radial;
  const dvec3 dw_dtheta = ct * s.t - st * radial;
  const dvec3 dw_dphi = ct * (-sp * s.n_prime + cp * s.b);
  const double wu = std::clamp(glm::dot(w, f.u), -1.0, 1.0), wn = glm::dot(w, f.n), wv = glm::dot(w, f.v);
  const double cos2 = std::max(wn * wn + wv * wv, 1e-8);  // cos²θ'
  const double theta_v = std::atan2(wu, std::sqrt(cos2)), phi_v = std::atan2(wv, wn);
  const int n = grids.resolution;
  const double h = std::numbers::pi / n;
  const double gi = std::clamp((theta_v + kHalfPi) / h - 0.5, 0.0, double(n - 1));
  const double gj = std::clamp((phi_v + kHalfPi) / h - 0.5, 0.0, double(n - 1));
  dvec3 g(0.0);
  for (int k = 0; k < 3; ++k) g += bary[k] * grids.bilinear(corners[k], gi, gj);
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
