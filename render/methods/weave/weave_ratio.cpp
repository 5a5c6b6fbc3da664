#include "methods/weave/weave_ratio.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/microcylinder.h"
#include "core/weave_coverage.h"
#include "methods/sg_lights.h"

namespace weft {

double weave_lobe_widening(double sharpness) { return 1.0 / (4.0 * std::max(sharpness, 1e-6)); }

HorizonLight horizon_light(const SphericalGaussian& g, const dvec3& n) {
  const double sigma = 1.0 / std::sqrt(std::max(g.sharpness, 1e-6));
  const double e0 = std::asin(std::clamp(glm::dot(g.axis, n), -1.0, 1.0));
  const double z = e0 / sigma;
  HorizonLight out;
  out.share = 0.5 * std::erfc(-z / std::sqrt(2.0));
  if (out.share <= 0.0) return out;
  const double lift = sigma * std::exp(-0.5 * z * z) / (std::sqrt(2.0 * std::numbers::pi) * out.share);
  const dvec3 level = g.axis - glm::dot(g.axis, n) * n;  // the axis's direction along the horizon
  const double level_length = glm::length(level);
  if (lift < 1e-9 || level_length < 1e-9) {
    out.axis = g.axis;
    return out;
  }
  const double e = std::min(e0 + lift, 0.5 * std::numbers::pi);
  out.axis = std::cos(e) * (level / level_length) + std::sin(e) * n;
  return out;
}

namespace {
// Both lobes of `thread` widened by the variance `widen2`: γ² → γ² + widen2.
ThreadParams widened_thread(ThreadParams thread, double widen2) {
  thread.gamma_s = std::sqrt(thread.gamma_s * thread.gamma_s + widen2);
  thread.gamma_v = std::sqrt(thread.gamma_v * thread.gamma_v + widen2);
  return thread;
}
}  // namespace

Fabric widened_fabric(Fabric fabric, double widen2) {
  for (auto& t : fabric.threads) t = widened_thread(t, widen2);
  return fabric;
}

namespace {
// Thread j's sample at tilt α: its P, and f_s·M·P·cos θ_i with both lobes widened by
// widen2 + (c·tilt_spread)², c = ½(cos φ_i + cos φ_o) (iwasaki.cpp's sample_lobe_width).
struct SampleTerms {
  double p = 0.0;   // P
  dvec3 value{0.0}; // f_s·M·P·cos θ_i
};
SampleTerms sample_terms(const ThreadParams& thread, const SurfaceFrame& frame, int j, double alpha, double tilt_spread,
                         double widen2, const dvec3& wi, const dvec3& wo) {
  SampleTerms out;
  const ThreadFrame f = thread_frame(frame, j, alpha);
  const FiberAngles in = fiber_angles(f, wi), o = fiber_angles(f, wo);
  out.p = projection(in, o);
  if (out.p <= 0.0) return out;
  const double w = masking(in, o) * out.p;
  if (w <= 0.0) return out;
  const double c = 0.5 * (std::cos(in.phi) + std::cos(o.phi));
  out.value = scattering(widened_thread(thread, widen2 + c * c * tilt_spread * tilt_spread), in, o) * (w * std::cos(in.theta));
  return out;
}
}  // namespace

WeaveTerms weave_terms(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                       std::span<const double> visibility) {
  if (!visibility.empty() && visibility.size() != sgs.size())
    throw std::invalid_argument("weave_terms: " + std::to_string(visibility.size()) + " visibilities for " +
                                std::to_string(sgs.size()) + " SGs");
  WeaveTerms t;
  const Fabric& fabric = bsdf.fabric();
  for (size_t i = 0; i < sgs.size(); ++i) {
    const SphericalGaussian& g = sgs[i];
    double q = (1.0 - fabric.threads[0].coverage - fabric.threads[1].coverage) * std::max(glm::dot(frame.n, wo), 0.0);
    dvec3 sum(0.0);
    const HorizonLight light = horizon_light(g, frame.n);
    const bool lit = light.share > 0.0 && glm::dot(frame.n, light.axis) > 0.0 && glm::dot(frame.n, wo) > 0.0;
    for (int j = 0; j < 2; ++j) {
      double p_sum = 0.0;
      dvec3 thread_sum(0.0);
      for (int k = 0; k < bsdf.sample_count(j); ++k) {
        const SampleTerms s = sample_terms(fabric.threads[j], frame, j, bsdf.tilt(j, k), bsdf.tilt_spread(j, k),
                                           weave_lobe_widening(g.sharpness), light.axis, wo);
        p_sum += s.p;
        thread_sum += s.value;
      }
      q += fabric.threads[j].coverage * p_sum / bsdf.sample_count(j);
      sum += fabric.threads[j].coverage * thread_sum / double(bsdf.sample_count(j));
    }
    const double weight = lit && q > kQFloor ? (visibility.empty() ? 1.0 : visibility[i]) / q : 0.0;
    t.q.push_back(q);
    t.weight.push_back(weight);
    t.fabric += weight * light.share * sg_power(g) * sum;
  }
  return t;
}

namespace {
// Σ_k P_k f_s M P cos θ_i · V_k/Q_k of thread j's sample at `arc` along its float, its lobes widened
// by `tilt_spread` (RMS, radians) besides each SG's own spread; SG k is the point light lights[k]
// (its horizon_light at frame.n).
dvec3 resolved_response(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, int thread, double arc,
                        double tilt_spread, const WeaveTerms& terms, std::span<const SphericalGaussian> sgs,
                        std::span<const HorizonLight> lights) {
  const double alpha = weave_tilt(bsdf.fabric(), WeaveSample{thread, arc});
  dvec3 resolved(0.0);
  if (glm::dot(frame.n, wo) <= 0.0) return resolved;
  for (size_t k = 0; k < sgs.size(); ++k) {
    const HorizonLight& light = lights[k];
    if (terms.weight.at(k) > 0.0 && light.share > 0.0 && glm::dot(frame.n, light.axis) > 0.0)
      resolved += light.share * sg_power(sgs[k]) * terms.weight[k] *
                  sample_terms(bsdf.fabric().threads[thread], frame, thread, alpha, tilt_spread,
                               weave_lobe_widening(sgs[k].sharpness), light.axis, wo).value;
  }
  return resolved;
}

// Each SG's horizon_light at normal n: what every float's shading in a pixel takes.
std::vector<HorizonLight> horizon_lights(std::span<const SphericalGaussian> sgs, const dvec3& n) {
  std::vector<HorizonLight> lights;
  lights.reserve(sgs.size());
  for (const auto& g : sgs) lights.push_back(horizon_light(g, n));
  return lights;
}

dvec3 ratio_to(const dvec3& resolved, const dvec3& fabric) {
  dvec3 ratio;
  for (int c = 0; c < 3; ++c) ratio[c] = fabric[c] > kWeaveRatioFloor ? std::min(resolved[c] / fabric[c], kWeaveRatioCap) : 1.0;
  return ratio;
}
}  // namespace

double weave_tilt_spread(const Fabric& fabric, int thread, double arc, double arc_spread) {
  if (arc_spread <= 0.0) return 0.0;
  const double h = std::sqrt(3.0) * arc_spread;  // the half-width of a uniform spread with that RMS
  auto tilt = [&](double a) { return weave_tilt(fabric, WeaveSample{thread, a}); };
  const double here = tilt(arc);
  double slope = std::numeric_limits<double>::infinity();
  if (arc < 1.0) {
    const double b = std::min(arc + h, 1.0);
    slope = std::abs(tilt(b) - here) / (b - arc);
  }
  if (arc > 0.0) {
    const double a = std::max(arc - h, 0.0);
    slope = std::min(slope, std::abs(here - tilt(a)) / (arc - a));
  }
  return std::isfinite(slope) ? slope * arc_spread : 0.0;
}

dvec3 weave_resolved_response(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, int thread, double arc,
                              double tilt_spread, const WeaveTerms& terms, std::span<const SphericalGaussian> sgs) {
  return resolved_response(bsdf, frame, wo, thread, arc, tilt_spread, terms, sgs, horizon_lights(sgs, frame.n));
}

dvec3 weave_ratio_of(const dvec3& resolved, const dvec3& fabric) { return ratio_to(resolved, fabric); }

dvec3 weave_ratio(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                  glm::dvec2 st, const WeaveTerms& terms, std::span<const SphericalGaussian> sgs) {
  const WeaveSample w = layout.at(st.x, st.y);
  if (w.thread < 0) return dvec3(0.0);
  return ratio_to(resolved_response(bsdf, frame, wo, w.thread, w.arc, 0.0, terms, sgs, horizon_lights(sgs, frame.n)),
                  terms.fabric);
}

dvec3 weave_float_response(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, const WeaveCoverage& c, int i,
                           const WeaveTerms& terms, std::span<const SphericalGaussian> sgs, std::span<const HorizonLight> lights) {
  const WeavePiece& p = c.piece[i];
  const Fabric& fabric = bsdf.fabric();
  // Once at the middle arc, widened by the tilts the whole footprint spans along the float.
  auto middle = [&] {
    return resolved_response(bsdf, frame, wo, p.thread, p.arc, weave_tilt_spread(fabric, p.thread, p.arc, c.arc_spread[p.thread]),
                             terms, sgs, lights);
  };
  if (p.arc_hi <= p.arc_lo) return middle();
  // Three-point Gauss–Legendre over each stretch of the range between the curve's jumps, each node
  // weighted by the footprint's density there and its lobes widened by the tilts of the part of
  // the stretch it stands for (its weight's share, as a uniform spread).
  constexpr double kNode = 0.7745966692414834, kWeights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  dvec3 sum(0.0);
  double total = 0.0;
  auto stretch = [&](double lo, double hi) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (int m = 0; m < 3; ++m) {
      const double a = mid + (m - 1) * kNode * half, w = kWeights[m] * half * arc_density(c, p, a);
      if (w <= 0.0) continue;
      const double part = kWeights[m] * 2.0 * half / std::sqrt(12.0);
      sum += w * resolved_response(bsdf, frame, wo, p.thread, a, weave_tilt_spread(fabric, p.thread, a, part), terms, sgs, lights);
      total += w;
    }
  };
  // A zero-length segment of the curve is a jump of the tilt at that arc (the velvet's pile).
  const TangentCurve& curve = fabric.threads[p.thread].curve;
  double from = p.arc_lo, arc = 0.0;
  for (double length : curve.lengths()) {
    if (length == 0.0) {
      const double jump = arc / curve.total_length();
      if (jump > from && jump < p.arc_hi) stretch(from, jump), from = jump;
    }
    arc += length;
  }
  stretch(from, p.arc_hi);
  return total > 0.0 ? sum / total : middle();
}

dvec3 weave_ratio_filtered(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                           glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, const WeaveTerms& terms,
                           std::span<const SphericalGaussian> sgs) {
  const WeaveCoverage c = weave_coverage(layout, st, dx, dy);
  const std::vector<HorizonLight> lights = horizon_lights(sgs, frame.n);
  dvec3 resolved(0.0);
  for (int i = 0; i < kWeaveCoveragePieces; ++i) {
    if (c.piece[i].thread < 0) break;
    resolved += piece_weight(c, i) * weave_float_response(bsdf, frame, wo, c, i, terms, sgs, lights);
  }
  return ratio_to(resolved, terms.fabric);
}

double weave_detail(double thread_footprint) {
  const double x = std::clamp((thread_footprint - kWeaveFineFootprint) / (kWeaveCoarseFootprint - kWeaveFineFootprint), 0.0, 1.0);
  return 1.0 - x * x * (3.0 - 2.0 * x);
}

dvec3 weave_factor(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                   glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, std::span<const SphericalGaussian> sgs,
                   std::span<const double> visibility) {
  const double detail = weave_detail(weave_thread_footprint(layout, std::max(glm::length(dx), glm::length(dy))));
  if (detail <= 0.0) return dvec3(1.0);
  const dvec3 r = weave_ratio_filtered(bsdf, layout, frame, wo, st, dx, dy, weave_terms(bsdf, frame, wo, sgs, visibility), sgs);
  return glm::mix(dvec3(1.0), r, detail);
}

}  // namespace weft
