#pragma once
// Ground truth for the `thin` method's single scattering (methods/thin/thin.h): the same optically
// thin layer, with the light integrated exactly instead of one lobe-axis evaluation per SG:
//   L_scatter(ω_o) = Σ_k ∫_{S²} G_k(ω) · μ₀ · K(μ, μ₀) dω,   μ₀ = |n·ω|,
// K = K_r for ω on the viewer's side of the layer, K_t for ω behind it. Each SG is integrated
// on its own warped midpoint grid (polar angle by the SG's inverse CDF, as sg_quadrature.h),
// doubled until the result moves by less than the tolerance.
#include <functional>
#include <span>

#include "core/spherical_gaussian.h"
#include "methods/thin/thin.h"

namespace weft {

struct ThinQuadratureResult {
  dvec3 radiance{0.0};
  bool converged = false;
  int polar_cells = 0;
};

struct ThinQuadratureOptions {
  double tolerance = 1e-4;  // relative change between grid doublings that counts as converged
  // > 0: one grid of fixed_polar × 2·fixed_polar cells per SG, no doubling (converged false).
  int fixed_polar = 0;
  // Visibility of a light direction from the layer (either side); empty: unoccluded.
  std::function<bool(const dvec3&)> visible;
};

// n faces the viewer (n·ω_o > 0; else the result is 0).
ThinQuadratureResult integrate_thin_scatter(const ThinParams& p, const dvec3& n, const dvec3& wo,
                                            std::span<const SphericalGaussian> sgs,
                                            const ThinQuadratureOptions& options = {});

}  // namespace weft
