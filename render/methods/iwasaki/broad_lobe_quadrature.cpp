#include "methods/iwasaki/broad_lobe_quadrature.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace weft {

dvec3 broad_lobe_radiance(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                          std::span<const SphericalGaussian> sgs, std::span<const int> slots,
                          std::span<const std::uint32_t> bits) {
  dvec3 out(0.0);
  if (glm::dot(wo, frame.n) <= 0.0) return out;
  ClothBsdf::Point point = bsdf.at(frame);
  for (size_t k = 0; k < sgs.size(); ++k) {
    if (slots[k] < 0) continue;
    const SgWarpedGrid grid(sgs[k].axis, sgs[k].sharpness, kBroadLobeGrid);
    dvec3 sum(0.0);
    for (int i = 0, c = 0; i < grid.polar(); ++i) {
      const double cos_t = grid.polar_cosine(i);
      for (int j = 0; j < grid.azimuthal(); ++j, ++c) {
        const dvec3 wi = grid.direction(cos_t, j);
        if (glm::dot(wi, frame.n) <= 0.0) continue;  // below the surface: the model is zero there
        if (!bits.empty() && !((bits[slots[k] * kBroadLobeWordsPerSg + c / 32] >> (c % 32)) & 1u)) continue;
        sum += point.integrand(wi, wo);
      }
    }
    out += sgs[k].amplitude * sum * grid.cell_weight();
  }
  return out;
}

IwasakiTerms iwasaki_narrow_radiance(const ClothBsdf& bsdf, const WeightingTables& tables, const SurfaceFrame& frame,
                                     const dvec3& wo, std::span<const SphericalGaussian> sgs, std::span<const int> slots,
                                     const IwasakiVisibility* visibility) {
  IwasakiTerms out;
  for (size_t k = 0; k < sgs.size(); ++k) {
    if (slots[k] >= 0) continue;
    const IwasakiTerms t = iwasaki_sg_radiance(bsdf, tables, frame, wo, sgs, k, visibility);
    out.surface += t.surface;
    out.volume += t.volume;
    out.radiance += t.radiance;
  }
  return out;
}

}  // namespace weft
