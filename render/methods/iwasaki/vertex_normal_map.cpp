#include "methods/iwasaki/vertex_normal_map.h"

#include <algorithm>
#include <cmath>

#include "core/normal_map_frame.h"
#include "methods/broad_lobe_bits.h"
#include "methods/sg_lights.h"
#include "methods/weave/weave_ratio.h"

namespace weft {

ClothBsdf normal_map_ratio_bsdf(const ClothBsdf& bsdf) {
  return ClothBsdf(bsdf.fabric(), std::array<int, 2>{std::min(bsdf.sample_count(0), kNormalMapRatioSamples),
                                                     std::min(bsdf.sample_count(1), kNormalMapRatioSamples)});
}

bool normal_map_tilts(const dvec3& t) { return std::max(std::abs(t.x), std::abs(t.y)) >= kNormalMapFlatTilt; }

dvec3 normal_map_lobe_response(const ClothBsdf& bsdf, const SurfaceFrame& frame, const SphericalGaussian& g,
                               const dvec3& wo) {
  const ClothBsdf wide(widened_fabric(bsdf.fabric(), weave_lobe_widening(g.sharpness)),
                       std::array<int, 2>{bsdf.sample_count(0), bsdf.sample_count(1)});
  const double c = glm::dot(g.axis, frame.n);
  const dvec3 wi = lift_to_cosine(g.axis, frame.n, sg_effective_cosine(g.sharpness, c));
  const ClothBsdf::Point::Split s = wide.at(frame).integrand_split(wi, wo);
  return sg_clamped_cosine_integral(g.sharpness, c) / std::max(glm::dot(frame.n, wi), kSgHorizonCosine) *
         dvec3(s.surface, s.volume[0], s.volume[1]);
}

dvec3 normal_map_lobe_ratio(const ClothBsdf& bsdf, const SurfaceFrame& surface, const SurfaceFrame& bumped,
                            const SphericalGaussian& g, const dvec3& wo) {
  const dvec3 below = normal_map_lobe_response(bsdf, surface, g, wo), above = normal_map_lobe_response(bsdf, bumped, g, wo);
  dvec3 r;
  for (int c = 0; c < 3; ++c)
    r[c] = std::min((above[c] + kNormalMapRatioBias) / (below[c] + kNormalMapRatioBias), kNormalMapRatioCap);
  return r;
}

dvec3 normal_map_cosine_ratio(const dvec3& n, const dvec3& bumped_n, const SphericalGaussian& g) {
  const double bias = kNormalMapRatioBias * sg_clamped_cosine_integral(g.sharpness, 1.0);
  const double r = (sg_clamped_cosine_integral(g.sharpness, glm::dot(g.axis, bumped_n)) + bias) /
                   (sg_clamped_cosine_integral(g.sharpness, glm::dot(g.axis, n)) + bias);
  return dvec3(std::min(r, kNormalMapRatioCap));
}

std::vector<dvec3> normal_map_ratios(const ClothBsdf& bsdf, const SurfaceFrame& surface, const dvec3& t,
                                     const dvec3& wo, std::span<const SphericalGaussian> sgs,
                                     std::span<const int> broad_slots, std::span<const double> light) {
  std::vector<dvec3> out(sgs.size(), dvec3(1.0));
  if (!normal_map_tilts(t)) return out;
  auto sharp = [&](size_t k) {
    return !(k < broad_slots.size() && broad_slots[k] >= 0) && sgs[k].sharpness >= kBroadLobeSharpness;
  };
  int first = -1, second = -1;
  double light_first = -1.0, light_second = -1.0;
  for (size_t k = 0; k < sgs.size(); ++k) {
    if (!sharp(k)) continue;
    if (light[k] > light_first) {
      second = first, light_second = light_first;
      first = int(k), light_first = light[k];
    } else if (light[k] > light_second) {
      second = int(k), light_second = light[k];
    }
  }
  const SurfaceFrame bumped = normal_mapped_frame(surface, t);
  for (size_t k = 0; k < sgs.size(); ++k) {
    if (!sharp(k)) continue;
    out[k] = int(k) == first || int(k) == second ? normal_map_lobe_ratio(bsdf, surface, bumped, sgs[k], wo)
                                                 : normal_map_cosine_ratio(surface.n, bumped.n, sgs[k]);
  }
  return out;
}

dvec3 normal_mapped_facet_radiance(const ClothBsdf& bsdf, std::span<const SphericalGaussian> sgs,
                                   std::span<const int> broad_slots,
                                   const std::array<std::span<const IwasakiTerms>, 3>& vertex_sgs, const dvec3& bary,
                                   const SurfaceFrame& surface, const dvec3& facet_normal,
                                   const std::array<dvec3, 2>& tint, const dvec3& t, const dvec3& wo) {
  std::vector<double> light(sgs.size());
  for (size_t k = 0; k < sgs.size(); ++k) {
    dvec3 blended(0.0);
    for (int i = 0; i < 3; ++i) blended += bary[i] * vertex_sgs[i][k].tinted(tint);
    const bool broad = k < broad_slots.size() && broad_slots[k] >= 0;
    if (!broad) blended *= facet_horizon_factor(sgs[k], surface.n, facet_normal);
    light[k] = blended.r + blended.g + blended.b;
  }
  const std::vector<dvec3> ratios = normal_map_ratios(bsdf, surface, t, wo, sgs, broad_slots, light);
  return facet_interpolated_radiance(sgs, broad_slots, vertex_sgs, bary, surface.n, facet_normal, tint, ratios);
}

}  // namespace weft
