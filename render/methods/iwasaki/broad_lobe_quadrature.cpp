#include "methods/iwasaki/broad_lobe_quadrature.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace weft {

IwasakiTerms broad_lobe_terms(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                              std::span<const SphericalGaussian> sgs, std::span<const int> slots,
                              std::span<const std::uint32_t> bits) {
  IwasakiTerms out;
  if (glm::dot(wo, frame.n) <= 0.0) return out;
  ClothBsdf::Point point = bsdf.at(frame);
  const auto& threads = bsdf.fabric().threads;
  for (size_t k = 0; k < sgs.size(); ++k) {
    if (slots[k] < 0) continue;
    const SgWarpedGrid grid(sgs[k].axis, sgs[k].sharpness, kBroadLobeGrid);
    ClothBsdf::Point::Split sum;
    for (int i = 0, c = 0; i < grid.polar(); ++i) {
      const double cos_t = grid.polar_cosine(i);
      for (int j = 0; j < grid.azimuthal(); ++j, ++c) {
        const dvec3 wi = grid.direction(cos_t, j);
        if (glm::dot(wi, frame.n) <= 0.0) continue;  // below the surface: the model is zero there
        if (!bits.empty() && !((bits[slots[k] * kBroadLobeWordsPerSg + c / 32] >> (c % 32)) & 1u)) continue;
        const ClothBsdf::Point::Split s = point.integrand_split(wi, wo);
        sum.surface += s.surface;
        sum.volume[0] += s.volume[0];
        sum.volume[1] += s.volume[1];
      }
    }
    const dvec3 mu = sgs[k].amplitude * grid.cell_weight();
    out.surface += mu * sum.surface;
    for (int j = 0; j < 2; ++j) out.thread_volume[j] += mu * threads[j].albedo * sum.volume[j];
  }
  out.volume = out.thread_volume[0] + out.thread_volume[1];
  out.radiance = out.surface + out.volume;
  return out;
}

dvec3 broad_lobe_radiance(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                          std::span<const SphericalGaussian> sgs, std::span<const int> slots,
                          std::span<const std::uint32_t> bits) {
  return broad_lobe_terms(bsdf, frame, wo, sgs, slots, bits).radiance;
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
    for (int j = 0; j < 2; ++j) out.thread_volume[j] += t.thread_volume[j];
  }
  return out;
}

}  // namespace weft
