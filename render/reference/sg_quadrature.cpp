#include "reference/sg_quadrature.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace weft {

namespace {

// ∫ G(ω) f(ω) dω over the hemisphere n·ω > 0 on the SG-warped n × 2n grid (SgWarpedGrid: every
// cell holds the same share of G, so the sum weights only f).
// `make_f()` returns the integrand f(ω_i) for one thread of execution (it may hold scratch).
template <class MakeIntegrand>
dvec3 integrate_one(const MakeIntegrand& make_f, const dvec3& normal, const SphericalGaussian& g, int n,
                    const SgQuadratureOptions& opt) {
  const SgWarpedGrid grid(g.axis, g.sharpness, n);
  const int n_phi = grid.azimuthal();
  double r = 0, gr = 0, b = 0;
#pragma omp parallel reduction(+ : r, gr, b) if (opt.parallel)
  {
    auto f = make_f();
#pragma omp for schedule(dynamic, 4)
    for (int i = 0; i < n; ++i) {
      const double cos_t = grid.polar_cosine(i);
      for (int k = 0; k < n_phi; ++k) {
        const dvec3 wi = grid.direction(cos_t, k);
        if (glm::dot(wi, normal) <= 0.0) continue;
        if (opt.visible && !opt.visible(wi)) continue;
        const dvec3 v = f(wi);
        r += v.r;
        gr += v.g;
        b += v.b;
      }
    }
  }
  return g.amplitude * dvec3(r, gr, b) * grid.cell_weight();
}

template <class MakeIntegrand>
dvec3 integrate_all(const MakeIntegrand& make_f, const dvec3& normal, std::span<const SphericalGaussian> sgs, int n,
                    const SgQuadratureOptions& opt) {
  dvec3 sum(0.0);
  for (const auto& g : sgs)
    if (g.amplitude != dvec3(0.0)) sum += integrate_one(make_f, normal, g, n, opt);
  return sum;
}

template <class MakeIntegrand>
SgQuadratureResult integrate(const MakeIntegrand& make_f, const dvec3& normal, std::span<const SphericalGaussian> sgs,
                             const SgQuadratureOptions& opt) {
  SgQuadratureResult res;
  const long long per_cell = static_cast<long long>(sgs.size()) * 2;
  if (opt.fixed_polar > 0) {
    const int n = opt.fixed_polar;
    res.radiance = integrate_all(make_f, normal, sgs, n, opt);
    res.evaluations = per_cell * n * n;
    res.polar_cells = n;
    return res;
  }
  int n = std::max(opt.min_polar, 4);
  dvec3 prev = integrate_all(make_f, normal, sgs, n, opt);
  res.evaluations += per_cell * n * n;
  while (true) {
    const int next = 2 * n;
    if (next > opt.max_polar) break;
    const dvec3 cur = integrate_all(make_f, normal, sgs, next, opt);
    res.evaluations += per_cell * next * next;
    const double scale = std::max({cur.r, cur.g, cur.b});
    const double change = scale > 0.0 ? glm::length(cur - prev) / glm::length(cur) : 0.0;
    n = next;
    prev = cur;
    res.last_change = change;
    if (change < opt.tolerance) {
      res.converged = true;
      break;
    }
  }
  res.radiance = prev;
  res.polar_cells = n;
  return res;
}

}  // namespace

SgQuadratureResult integrate_sg_lighting(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                                         std::span<const SphericalGaussian> sgs, const SgQuadratureOptions& opt) {
  return integrate_sg_lighting(bsdf, frame, wo, sgs, {dvec3(1.0), dvec3(1.0)}, opt);
}

SgQuadratureResult integrate_sg_lighting(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                                         std::span<const SphericalGaussian> sgs, const std::array<dvec3, 2>& tint,
                                         const SgQuadratureOptions& opt) {
  if (glm::dot(wo, frame.n) <= 0.0 || sgs.empty()) {
    SgQuadratureResult res;
    res.converged = true;
    return res;
  }
  auto make_f = [&] {
    return [point = bsdf.at(frame), &wo, &tint](const dvec3& wi) mutable { return point.integrand(wi, wo, tint); };
  };
  return integrate(make_f, frame.n, sgs, opt);
}

SgQuadratureResult integrate_sg_resolved(const ClothBsdf& bsdf, const SurfaceFrame& frame, int thread, double tilt,
                                         const dvec3& wo, std::span<const SphericalGaussian> sgs,
                                         const SgQuadratureOptions& opt) {
  if (glm::dot(wo, frame.n) <= 0.0 || sgs.empty()) {
    SgQuadratureResult res;
    res.converged = true;
    return res;
  }
  auto make_f = [&] {
    return [point = bsdf.at(frame), &wo, thread, tilt](const dvec3& wi) mutable {
      return point.resolved_integrand(thread, tilt, wi, wo);
    };
  };
  return integrate(make_f, frame.n, sgs, opt);
}

SgQuadratureResult integrate_sg_lambertian(const dvec3& n, const dvec3& albedo, std::span<const SphericalGaussian> sgs,
                                           const SgQuadratureOptions& opt) {
  if (sgs.empty()) {
    SgQuadratureResult res;
    res.converged = true;
    return res;
  }
  const dvec3 brdf = albedo / std::numbers::pi;
  auto make_f = [&] { return [&](const dvec3& wi) { return brdf * glm::dot(n, wi); }; };
  return integrate(make_f, n, sgs, opt);
}

}  // namespace weft
