#pragma once
// The approximation of seed 001 (Mizutani et al., "Interactive Cloth Rendering and Appearance Editing
// under Environment Lighting", §3) of L_o at one cloth point under SGs, without visibility:
//
//   L_o = Σ_k μ_k Σ_j (1/N_j) Σ_{t∈C_j} T_{t,λ_k}(ξ_k, ω_o) · ∫ G_k f_s cos θ_i dω_i          (Eq. 8–9)
//
// The weighting factor T is seed 001 Eq. 9, the same SG-convolved W that seed 000 Eq. 10 bakes
// (docs/design.md §2: one W), so this method reads the same WeightingTables as `iwasaki`.
// The shading factor ∫ G_k f_s cos θ_i dω_i, per lobe (Eq. 10–16):
//  - G_k = g^c(θ_i;θ_k,σ_k)·g^c(φ_i;φ_k,σ'_k), σ'_k = σ_k/√(cosθ_i cosθ_k) (Eq. 10);
//  - the longitudinal lobe g^u(θ_h;γ) ≈ g^c(θ_i;−θ_o,2γ)/(√πγ), merged with the SG's θ factor
//    into α·g^c(θ_i;θ_l,σ_l) (Eq. 11, appendix Eq. 17);
//  - Fresnel by Schlick, F_r ≈ F_0 + (1−F_0)(1 − cosθ_d·x)⁵ with x = cos(φ_d/2), expanded in
//    powers of x (Eq. 12–13); the volume lobe's F = (1−F_r)² is the square of that polynomial
//    (powers 2..10). Each power x^m integrates against g^c(φ_i) into the table T_m(φ_o,φ_k,σ'_k)
//    (Eq. 14, render/runtime/azimuthal_table.h);
//  - the θ_i integral ∫ g(θ_i;θ_l,σ_l) h(θ_i) dθ_i, g^c replaced by the Gaussian g, with
//    h = cos²θ_i/cos²θ_d · Σ C_m(θ_d) T_m(σ'_k(θ_i)) (Eq. 16; the volume lobe divides h by
//    cosθ_i + cosθ_o) linear on 6 equal segments of [−π/2, π/2], each segment in closed form.
// The isotropic k_d part of the volume lobe has no longitudinal lobe: its Gaussian is the SG's.
//
// The GLSL twin is render/methods/mizutani/mizutani.frag; tests/gpu/mizutani_parity_test.cpp pins them.
#include <span>

#include "runtime/azimuthal_table.h"
#include "runtime/weighting_tables.h"
#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"

namespace weft {

struct MizutaniTerms {
  dvec3 radiance{0.0};
  dvec3 surface{0.0};  // Σ over the f_rs part
  dvec3 volume{0.0};   // Σ over the f_rv part
};

// Segments of the piecewise-linear θ_i integral (seed 001: "6 segments suffice").
inline constexpr int kMizutaniThetaSegments = 6;

// ∫_a^b g(θ;μ,σ)·(c0 + c1·(θ − a)) dθ with g = exp(−(θ−μ)²/σ²), in closed form (erf); σ = +∞
// (or ≥ 1e4, where the erf difference cancels) is the constant 1. Returned as the pair
// (∫ g, ∫ (θ − a) g) so h's end values combine with it.
struct SegmentMoments {
  double m0 = 0.0, m1 = 0.0;
};
SegmentMoments gaussian_segment_moments(double a, double b, double mu, double sigma);

// The shading factor of one tangent sample and one unit-amplitude SG: ∫ G f_rs cos θ_i dω_i
// (surface, white) and ∫ G f_rv cos θ_i dω_i / A (volume, per unit albedo), over the half-space
// φ_i ∈ [−π/2, π/2] of the sample's n' (where its masking term lives), by Eq. 10–16.
struct MizutaniShading {
  double surface = 0.0, volume = 0.0;
};
MizutaniShading mizutani_shading(const ThreadParams& thread, const ThreadFrame& frame, const dvec3& wo,
                                 const SphericalGaussian& sg, const AzimuthalTable& azimuthal);

// `bsdf` supplies the thread parameters (A, γ_s, γ_v, η, k_d: the knobs) and the tangent
// samples, which must be those `weights` was baked for.
MizutaniTerms mizutani_radiance(const ClothBsdf& bsdf, const WeightingTables& weights,
                                const AzimuthalTable& azimuthal, const SurfaceFrame& frame, const dvec3& wo,
                                std::span<const SphericalGaussian> sgs);

}  // namespace weft
