#pragma once
// Ground-truth outgoing radiance at one surface point lit by spherical Gaussians:
//   L_o(ω_o) = Σ_k ∫_{n·ω_i>0} G_k(ω_i) V(ω_i) · integrand(ω_i, ω_o) dω_i.
// Each SG's integral is taken in that SG's own frame with the polar angle warped by the
// SG's exact inverse CDF, so the Gaussian factor is constant in the warped variable and only
// the model's own features need resolving, however sharp the light (λ up to 10⁴). The
// midpoint grid is doubled until the result changes by less than the tolerance, or, for whole
// images, taken at one fixed level (`fixed_polar`) whose convergence the caller measures.
#include <functional>
#include <span>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"

namespace weft {

struct SgQuadratureOptions {
  double tolerance = 0.002;  // relative change between two grid levels that counts as converged
  int min_polar = 64;        // first grid: min_polar × 2·min_polar cells per SG
  int max_polar = 1024;      // gives up (converged = false) past this
  // > 0: a single grid of fixed_polar × 2·fixed_polar cells per SG, no doubling (converged is
  // then reported false: the caller judges convergence, e.g. by doubling it image-wide).
  int fixed_polar = 0;
  // Spread each SG's cells over OpenMP threads. Off when the caller already parallelises
  // (an image renderer running one point per thread).
  bool parallel = true;
  // Visibility V(ω_i) at the point; empty means unoccluded.
  std::function<bool(const dvec3&)> visible;
};

struct SgQuadratureResult {
  dvec3 radiance{0.0};
  bool converged = false;
  int polar_cells = 0;        // of the last grid
  long long evaluations = 0;  // integrand evaluations, all levels
  double last_change = 0.0;   // relative change at the last doubling
};

// The cloth model of docs/design.md §2 (ClothBsdf::Point::integrand) at `frame`.
SgQuadratureResult integrate_sg_lighting(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                                         std::span<const SphericalGaussian> sgs,
                                         const SgQuadratureOptions& options = {});
// The same with each thread's albedo multiplied by tint[j] (a texture's texel at the point).
SgQuadratureResult integrate_sg_lighting(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                                         std::span<const SphericalGaussian> sgs, const std::array<dvec3, 2>& tint,
                                         const SgQuadratureOptions& options = {});

// The resolved weave at one point of the repeat: thread `thread`'s sample at tilt `tilt`
// (ClothBsdf::Point::resolved_integrand) in place of the fabric-level integrand.
SgQuadratureResult integrate_sg_resolved(const ClothBsdf& bsdf, const SurfaceFrame& frame, int thread, double tilt,
                                         const dvec3& wo, std::span<const SphericalGaussian> sgs,
                                         const SgQuadratureOptions& options = {});

// A Lambertian surface (albedo/π · n·ω_i) with normal n: the floors and occluders of scenes.
SgQuadratureResult integrate_sg_lambertian(const dvec3& n, const dvec3& albedo,
                                           std::span<const SphericalGaussian> sgs,
                                           const SgQuadratureOptions& options = {});

}  // namespace weft
