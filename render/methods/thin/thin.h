#pragma once
// Method `thin` (seed 004: Chandrasekhar's optically thin plane-parallel layer, as Blinn's
// equations): thin cloth such as a curtain as a layer of optical thickness τ and isotropic
// single-scattering albedo A over a reflection method.
//  - Direct transmission: what lies behind shows through with alpha e^{−τ/μ}, μ = |n·ω_o|
//    (seed 004 Eq. 9: L = L_behind·α + L_source), the same front-lit and back-lit.
//  - Single scattering of light with irradiance E arriving at cosine μ₀ (derived from the
//    slab equation with source A/(4π)·(E/μ₀)·e^{−t/μ₀} at optical depth t):
//      reflection (light on the viewer's side)   K_r = A/(4π) · (1 − e^{−τ(1/μ+1/μ₀)}) / (μ + μ₀)
//      transmission (light on the far side)      K_t = A/(4π) · (e^{−τ/μ} − e^{−τ/μ₀}) / (μ − μ₀)
//    (K_t → A/(4π)·τ/μ²·e^{−τ/μ} as μ₀ → μ), radiance = Σ E·K over the light.
//    Runtime: per SG and side, E_k from the SG irradiance and μ₀ the lobe's G-weighted mean
//    cosine on that side (sg_effective_cosine, methods/sg_lights.h). Reference (reference/thin_quadrature.h): ∫ G(ω)·μ₀·K(μ₀) dω exactly.
//  - Composition: source = (1 − α)·L_reflection + L_scatter, the reflection method's radiance
//    scaled by the layer's coverage of the pixel (sgpoint for `thin`; iwasaki with its
//    visibility for `sheer`, methods/sheer/sheer.h).
// Parameters: τ is the fabric's optical_thickness (a sheer preset such as polyester_voile, or a
// scene's override); the Table II presets carry none and get τ = 0.5 (seed 004: within 1 % of
// the multiple-scattering answer for τ ≤ 0.2, their flag used τ = 2). A is the coverage-weighted
// thread colour normalised to a maximum of 0.8 (a light, thin fabric scatters most of what it
// stops). Mirrored by methods/thin/thin.glsl.
#include <span>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"

namespace weft {

struct ThinParams {
  double tau = 0.5;
  dvec3 albedo{0.8};
};

// τ given to a fabric without an optical thickness of its own.
inline constexpr double kDefaultThinTau = 0.5;
// The layer of `fabric`: τ its optical_thickness (kDefaultThinTau when it has none), A as above.
ThinParams thin_params(const Fabric& fabric);

// e^{−τ/μ}, μ floored at 1e-4.
double thin_alpha(const ThinParams& p, double mu);
// K_r and K_t above (per unit irradiance); μ, μ₀ in (0, 1].
dvec3 thin_reflection_kernel(const ThinParams& p, double mu, double mu0);
dvec3 thin_transmission_kernel(const ThinParams& p, double mu, double mu0);

// Share of one SG's light that reaches the layer on each side (1: unoccluded): `front` on n's
// side (the viewer's), `back` on the far side. A method with visibility gives one per SG.
struct ThinSideVisibility {
  double front = 1.0, back = 1.0;
};

// Single-scattered radiance toward ω_o (n facing the viewer) from SG light on both sides, each
// SG's irradiance on a side scaled by its share there (`visibility`: one per SG, or empty).
dvec3 thin_scatter(const ThinParams& p, const dvec3& n, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                   std::span<const ThinSideVisibility> visibility = {});

struct ThinShade {
  dvec3 source{0.0};  // premultiplied: added to α·L_behind
  double alpha = 1.0;
};
// The layer over any reflection method: `reflection` is that method's radiance at the frame
// (n facing ω_o). thin_radiance below is this with sgpoint.
ThinShade thin_compose(const ThinParams& p, const dvec3& n, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                       const dvec3& reflection, std::span<const ThinSideVisibility> visibility = {});

// The whole `thin` method over sgpoint reflection; `frame.n` is turned to face ω_o.
ThinShade thin_radiance(const ClothBsdf& bsdf, const ThinParams& p, SurfaceFrame frame, const dvec3& wo,
                        std::span<const SphericalGaussian> sgs);

}  // namespace weft
