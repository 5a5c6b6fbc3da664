#include "methods/sheer/sheer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/circular_gaussian.h"

namespace weft {

namespace {
// Below this horizon H the lobe hardly reaches the side at all: the share's ratio is not formed.
constexpr double kHorizonFloor = 1e-3;
}  // namespace

double sheer_sdf_share(const SphericalGaussian& g, const SurfaceFrame& mesh_frame, const dvec3& sdf,
                       const SigmoidGainTable* kappa) {
  const dvec3 w = glm::normalize(g.axis);
  const double wu = std::clamp(glm::dot(w, mesh_frame.u), -1.0, 1.0), wn = glm::dot(w, mesh_frame.n),
               wv = glm::dot(w, mesh_frame.v);
  // (θ', φ') as SgVisibility::compute looks the SDF up.
  const double theta = std::atan2(wu, std::sqrt(std::max(wn * wn + wv * wv, 1e-8))), phi = std::atan2(wv, wn);
  const double sigma = sg_bandwidth(g.sharpness);
  const double sigma_p = sigma / std::sqrt(std::max(std::cos(theta) * std::cos(theta), 1e-6));
  const double h = kappa ? kappa->h(sigma, sigma_p, sdf.x, sdf.y, sdf.z)
                         : linear_visibility_ratio(sigma, sigma_p, sdf.x, sdf.y, sdf.z);
  // The vertex frame is thread 1's sample frame at tilt 0 (t = u, n' = n, b = v).
  const double horizon = horizon_ratio(thread_frame(mesh_frame, 0, 0.0), mesh_frame.n, theta, phi, sigma, sigma_p);
  return std::clamp(h / std::max(horizon, kHorizonFloor), 0.0, 1.0);
}

ThinShade sheer_radiance(const ClothBsdf& bsdf, const WeightingTables& tables, const ThinParams& layer,
                         const SurfaceFrame& mesh_frame, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                         const IwasakiVisibility* visibility, std::span<const double> mesh_side) {
  if (!mesh_side.empty() && mesh_side.size() != sgs.size())
    throw std::invalid_argument("sheer_radiance: one visibility share per SG");
  SurfaceFrame f = mesh_frame;
  const bool flipped = glm::dot(f.n, wo) < 0.0;
  if (flipped) {  // the side facing the viewer, as the GPU does
    f.n = -f.n;
    f.v = glm::cross(f.n, f.u);
  }
  IwasakiVisibility on_side;
  if (visibility) on_side = on_side_shaded(*visibility, flipped);
  const dvec3 reflection = iwasaki_radiance(bsdf, tables, f, wo, sgs, visibility ? &on_side : nullptr).radiance;
  std::vector<ThinSideVisibility> sides;
  for (double share : mesh_side) sides.push_back(flipped ? ThinSideVisibility{1.0, share} : ThinSideVisibility{share, 1.0});
  return thin_compose(layer, f.n, wo, sgs, reflection, sides);
}

}  // namespace weft
