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

namespace {
// Σ_k P_k f_s M P cos θ_i / Q_k of thread j's sample at `arc` along its float.
dvec3 resolved_response(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, int thread, double arc,
                        const WeaveVertexTerms& terms, std::span<const SphericalGaussian> sgs) {
  const double alpha = weave_tilt(bsdf.fabric(), WeaveSample{thread, arc});
  dvec3 resolved(0.0);
  for (size_t k = 0; k < sgs.size(); ++k)
    if (terms.q.at(k) > kQFloor)
      resolved += sg_power(sgs[k]) * widened_for(bsdf, sgs[k]).at(frame).resolved_scattering(thread, alpha, sgs[k].axis, wo) /
                  terms.q[k];
  return resolved;
}

dvec3 ratio_to(const dvec3& resolved, const dvec3& fabric) {
  dvec3 ratio;
  for (int c = 0; c < 3; ++c) ratio[c] = fabric[c] > kWeaveRatioFloor ? std::min(resolved[c] / fabric[c], kWeaveRatioCap) : 1.0;
  return ratio;
}
}  // namespace

dvec3 weave_ratio(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                  glm::dvec2 st, const WeaveVertexTerms& terms, std::span<const SphericalGaussian> sgs) {
  const WeaveSample w = layout.at(st.x, st.y);
  if (w.thread < 0) return dvec3(0.0);
  return ratio_to(resolved_response(bsdf, frame, wo, w.thread, w.arc, terms, sgs), terms.fabric);
}

dvec3 weave_ratio_filtered(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                           glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, const WeaveVertexTerms& terms,
                           std::span<const SphericalGaussian> sgs) {
  WeaveSample samples[4];
  struct Share {
    int count = 0;
    double sum = 0.0, lo = 1.0, hi = 0.0;
  } share[2];
  for (int i = 0; i < 4; ++i) {
    const glm::dvec2 p = st + kWeaveFootprintGrid[i].x * dx + kWeaveFootprintGrid[i].y * dy;
    samples[i] = layout.at(p.x, p.y);
    if (samples[i].thread < 0) continue;
    Share& s = share[samples[i].thread];
    ++s.count;
    s.sum += samples[i].arc;
    s.lo = std::min(s.lo, samples[i].arc);
    s.hi = std::max(s.hi, samples[i].arc);
  }
  dvec3 resolved(0.0);
  for (int j = 0; j < 2; ++j) {
    const Share& s = share[j];
    if (s.count == 0) continue;
    if (s.hi - s.lo <= kWeaveArcSpread) {
      resolved += 0.25 * s.count * resolved_response(bsdf, frame, wo, j, s.sum / s.count, terms, sgs);
      continue;
    }
    for (const WeaveSample& w : samples)
      if (w.thread == j) resolved += 0.25 * resolved_response(bsdf, frame, wo, j, w.arc, terms, sgs);
  }
  return ratio_to(resolved, terms.fabric);
}

double weave_detail(double thread_footprint) {
  const double x = std::clamp((thread_footprint - kWeaveFineFootprint) / (kWeaveCoarseFootprint - kWeaveFineFootprint), 0.0, 1.0);
  return 1.0 - x * x * (3.0 - 2.0 * x);
}

dvec3 weave_factor(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                   glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, std::span<const SphericalGaussian> sgs) {
  const double detail = weave_detail(weave_thread_footprint(layout, std::max(glm::length(dx), glm::length(dy))));
  if (detail <= 0.0) return dvec3(1.0);
  const dvec3 r = weave_ratio_filtered(bsdf, layout, frame, wo, st, dx, dy, weave_vertex_terms(bsdf, frame, wo, sgs), sgs);
  return glm::mix(dvec3(1.0), r, detail);
}

}  // namespace weft
