#pragma once
// How the SG-lit runtime methods (sheen, mdfrot, thin) light a point: each SG becomes one
// light carrying the SG's exact-to-fit irradiance E_k(n) = ∫ G_k max(n·ω,0) dω (Tokuyoshi's
// clamped-cosine fit, core/spherical_gaussian.h), arriving from the SG's axis. The BRDF is
// evaluated once per SG at that axis, so the cosine-weighted power is right and only the
// BRDF's variation across the lobe is lost (exact as λ → ∞). An axis at or below the horizon
// still delivers irradiance when the lobe is wide; its direction is lifted to a fixed small
// elevation so the BRDF sees a valid direction. Mirrored by shaders/sg_lighting.glsl.
#include <glm/glm.hpp>

#include "core/spherical_gaussian.h"

namespace weft {

// Cosine of the lowest direction a lifted SG axis may have (≈ 1.1° above the horizon).
inline constexpr double kSgHorizonCosine = 0.02;

// `axis` moved along the great circle through `n` until n·axis ≥ kSgHorizonCosine (unchanged
// when already above). The antipode of n goes to any direction at that elevation.
glm::dvec3 lift_above_horizon(const glm::dvec3& axis, const glm::dvec3& n);
// The same rule to n·axis ≥ h (h in [0, 1)).
glm::dvec3 lift_to_cosine(const glm::dvec3& axis, const glm::dvec3& n, double h);

// The G-weighted mean cosine over the hemisphere around n, E/H with E the clamped-cosine and H
// the hemisphere integral (both Tokuyoshi fits), clamped to [kSgHorizonCosine, 1]: the one
// incidence cosine that stands for a whole lobe where a method needs only the cosine (thin's
// kernels). Equals n·ξ for a narrow lobe above the horizon. `c` = n·ξ.
double sg_effective_cosine(double sharpness, double c);

// Whole-sphere power ∫ G dω along the axis: sgpoint's light.
glm::dvec3 sg_power(const SphericalGaussian& g);

}  // namespace weft
