#pragma once
// Floors and occluders: Lambertian surfaces under the SGs, shadowed like the cloth
// (seed 000 §3.2) — the same baked SDF per vertex (bake/visibility/scene_visibility.h), read at the
// SG axes when the lighting changes (SgVisibility), and the same visibility ratio H of Eq. 12–14.
//
// Per vertex and SG G_k: E_k = irradiance(G_k, n) · min(1, H_sdf / H_horizon), where
//  - irradiance(G_k, n) is the clamped-cosine integral in closed form (core/spherical_gaussian.h);
//  - the lobe whose visible share H measures is G_k · cos, the cosine as an SG around n
//    (λ_c = 2.133, the usual fit): for broad lights the product leans towards the normal;
//  - H_sdf is H of the SDF linearised at that lobe's peak (d carried from the SG axis, where
//    SgVisibility holds it, along ∇d), the κ table's sigmoid when the bundle has one;
//  - H_horizon is H of the surface's own horizon for the same lobe: the bake counts everything
//    below the surface as occluded, which the clamped cosine has already cut away, so the
//    ratio keeps only what the occluders take.
// tests/methods/lambert_visibility_test.cpp holds this against ray-cast quadrature on a shadowed floor:
// 2.0 % relative RMSE (unshadowed 26 %); with the SG's own axis and width instead of G_k · cos
// 4.1 %, without dividing out the horizon 2.5 %.
#include <span>

#include "runtime/sigmoid_gain_table.h"
#include "core/microcylinder.h"
#include "core/spherical_gaussian.h"
#include "methods/sg_visibility.h"

namespace weft {

// Irradiance at vertex `vertex` (frame `frame`, the bake's: SurfaceFrame::from_normal_warp) from
// `sgs`; `visibility` (computed for exactly these SGs) may be null: unshadowed.
dvec3 lambert_irradiance(std::span<const SphericalGaussian> sgs, const SurfaceFrame& frame,
                         const SgVisibility* visibility, size_t vertex, const SigmoidGainTable* kappa);

// The visible share of SG `g`'s Lambert lobe given the SDF sample (d, ∂d/∂θ', ∂d/∂φ') at g's
// axis, in the vertex frame (visibility_sdf.h's parametrisation).
double lambert_visible_share(const SphericalGaussian& g, const SurfaceFrame& frame, const dvec3& sdf_at_axis,
                             const SigmoidGainTable* kappa);

}  // namespace weft
