#pragma once
// Method `sheen` (docs/design.md §4): what a glTF / Filament viewer shows for cloth — Lambert plus
// the Charlie sheen lobe (Estevez & Kulla 2017: D = (2 + 1/α)·sin^{1/α}θ_h / 2π) with
// Neubelt's visibility V = 1/(4(n·l + n·v − n·l·n·v)), as Filament's cloth model and
// KHR_materials_sheen do (without the albedo-scaling LUT: the two lobes simply add).
// Lit by the SGs as in methods/sg_lights.h. Mirrored by methods/sheen/sheen.glsl.
//
// Fabric → sheen parameters (each thread weighted by its coverage w_j = a_j/(a_1+a_2)):
//  - diffuse (Lambert reflectance) = Σ w_j A_j, the threads' colour;
//  - sheen colour = Σ w_j F_r(η_j, 1), the fibres' uncoloured normal-incidence reflectance;
//  - roughness α = (Σ w_j γ_s,j)²: near grazing sin^{1/α}θ_h ≈ exp(−x²/(2α)) in the angle x
//    from grazing, a Gaussian of deviation √α, matched to the surface lobe's deviation γ_s.
//    Clamped to [0.01, 1].
#include <array>
#include <span>

#include "core/fabric.h"
#include "core/microcylinder.h"
#include "core/spherical_gaussian.h"

namespace weft {

struct SheenParams {
  dvec3 diffuse{0.5};
  std::array<dvec3, 2> thread_diffuse{dvec3(0.25), dvec3(0.25)};  // w_j A_j: diffuse is their sum
  dvec3 sheen_colour{0.04};
  double roughness = 0.3;  // α
};

SheenParams sheen_params(const Fabric& fabric);
// A textured cloth at a point: each thread's part of the diffuse times its texel tint[j].
SheenParams sheen_tinted(SheenParams p, const std::array<dvec3, 2>& tint);

// Charlie distribution and Neubelt visibility, as above (n·h, n·l, n·v in [0, 1]).
double charlie_distribution(double alpha, double n_dot_h);
double neubelt_visibility(double n_dot_l, double n_dot_v);

// BRDF (no cosine); 0 when either direction is below n.
dvec3 sheen_brdf(const SheenParams& p, const dvec3& n, const dvec3& wi, const dvec3& wo);

// L_o = Σ_k E_k(n) · f(lifted ξ_k, ω_o) for n·ω_o > 0 (n facing the viewer), else 0.
dvec3 sheen_radiance(const SheenParams& p, const dvec3& n, const dvec3& wo, std::span<const SphericalGaussian> sgs);

}  // namespace weft
