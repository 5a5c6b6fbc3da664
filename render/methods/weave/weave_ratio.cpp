#include "methods/weave/weave_ratio.h"

#include <algorithm>
#include <cmath>

#include "methods/sg_lights.h"

namespace weft {

double weave_lobe_widening(double sharpness) { return 1.0 / (4.0 * std::max(sharpness, 1e-6)); }

Fabric widened_fabric(Fabric fabric, double widen2) {
  for (auto& t : fabric.threads) {
    t.gamma_s = std::sqrt(t.gamma_s * t.gamma_s + widen2);
    t.gamma_v = std::sqrt(t.gamma_v * t.gamma_v + widen2);
  }
  return fabric;
}

namespace {
// The bsdf with its lobes widened for SG g (same tangent samples).
ClothBsdf widened_for(const ClothBsdf& bsdf, const SphericalGaussian& g) {
  return ClothBsdf(widened_fabric(bsdf.fabric(), weave_lobe_widening(g.sharpness)),
                   std::array<int, 2>{bsdf.sample_count(0), bsdf.sample_count(1)});
}
}  // namespace

WeaveVertexTerms weave_vertex_terms(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                                    std::span<const SphericalGaussian> sgs) {
  WeaveVertexTerms t;
  auto point = bsdf.at(frame);
  for (const auto& g : sgs) {
    const ClothBsdf wide = widened_for(bsdf, g);
    t.fabric += sg_power(g) * wide.at(frame).integrand(g.axis, wo);
    t.q.push_back(point.q(g.axis, wo));
  }
  return t;
}

dvec3 weave_ratio(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                  glm::dvec2 st, const WeaveVertexTerms& terms, std::span<const SphericalGaussian> sgs) {
  const WeaveSample w = layout.at(st.x, st.y);
  if (w.thread < 0) return dvec3(0.0);
  const double alpha = weave_tilt(bsdf.fabric(), w);
  dvec3 resolved(0.0);
  for (size_t k = 0; k < sgs.size(); ++k)
    if (terms.q.at(k) > kQFloor)
      resolved += sg_power(sgs[k]) * widened_for(bsdf, sgs[k]).at(frame).resolved_scattering(w.thread, alpha, sgs[k].axis, wo) /
                  terms.q[k];
  dvec3 ratio;
  for (int c = 0; c < 3; ++c) ratio[c] = terms.fabric[c] > kWeaveRatioFloor ? std::min(resolved[c] / terms.fabric[c], kWeaveRatioCap) : 1.0;
  return ratio;
}

double weave_detail(double footprint) {
  const double x = std::clamp((footprint - kWeaveFineFootprint) / (kWeaveCoarseFootprint - kWeaveFineFootprint), 0.0, 1.0);
  return 1.0 - x * x * (3.0 - 2.0 * x);
}

dvec3 weave_factor(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                   glm::dvec2 st, double footprint, std::span<const SphericalGaussian> sgs) {
  const double detail = weave_detail(footprint);
  if (detail <= 0.0) return dvec3(1.0);
  const dvec3 r = weave_ratio(bsdf, layout, frame, wo, st, weave_vertex_terms(bsdf, frame, wo, sgs), sgs);
  return glm::mix(dvec3(1.0), r, detail);
}

}  // namespace weft
