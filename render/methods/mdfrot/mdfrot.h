#pragma once
// Method `mdfrot` (seed 002, Kang & Cho): a cheap weave model.
//  - Alternating anisotropy: each thread is an Ashikhmin–Shirley BRDF whose narrow direction
//    runs along that thread (warp: u, weft: v), so the two threads' highlights differ.
//  - Procedural yarn normals: the perturbed normal ñ of a yarn point tilts along the thread
//    by the tangent curve's tilt α (docs/design.md §2's samples, so each fabric's weave profile is
//    its own Table II curve) and across it by ±β (the yarn's round cross-section, β = 15°,
//    alternating between samples).
//  - Approximate MDF rotation (Eq. 9–11): the distribution is evaluated at h̃ = R̃ᵀh in the
//    unperturbed thread frame (x along the thread, y across, z = n), with
//    h̃ = (ñ_z h_x − ñ_x h_z, −ñ_x ñ_y h_x + (1 − ñ_y²) h_y + ñ_y ñ_z h_z, ñ·h)
//    (the extraction's third row reads ñ·ñ; Eq. 9's third row of R̃ᵀ is ñ, so it is ñ·h).
// The weave repeat is far below a pixel at showroom distance, so instead of a texture-space
// pattern (which would alias) each pixel averages the pattern: the thread's N tangent samples,
// weighted by coverage w_j = a_j/(a_1+a_2). The geometric terms (n·k, Fresnel at k·h) use the
// macro normal, as the seed keeps them.
// Parameters per thread: exponent along the thread n_u = 1/γ_s² (cos^n x ≈ e^{−n x²/2}:
// deviation γ_s, the microcylinder's surface lobe), across n_v = 1 (a cylinder reflects over
// its whole circumference), R_s = F_r(η, 1), R_d = A.
// Lit by the SGs as in methods/sg_lights.h. Mirrored by methods/mdfrot/mdfrot.glsl.
#include <span>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"

namespace weft {

inline constexpr int kMdfrotSamples = 8;           // tangent samples per thread (default)
inline constexpr int kMdfrotMaxSamples = 16;       // MDF_MAX_SAMPLES in the shader
inline constexpr double kMdfrotBulge = 0.2617993877991494;  // β = 15°

struct MdfrotThread {
  dvec3 diffuse{0.3};  // R_d
  double f0 = 0.04;    // R_s
  double n_along = 100.0, n_across = 1.0;
  double weight = 0.5; // w_j
  std::vector<double> tilts;  // α of each sample (radians)
};

struct MdfrotParams {
  MdfrotThread threads[2];
  double bulge = kMdfrotBulge;
};

MdfrotParams mdfrot_params(const Fabric& fabric, int samples = kMdfrotSamples);

// ñ in the thread frame (x along, y across, z = n) for tilt α and cross tilt β.
dvec3 mdfrot_perturbed_normal(double alpha, double beta);
// Eq. 11: h̃ = R̃ᵀ h, both in the thread frame.
dvec3 mdfrot_rotate_half(const dvec3& n_tilde, const dvec3& h);

// BRDF (no cosine) at frame (n, u, v = n × u); 0 when either direction is below n.
dvec3 mdfrot_brdf(const MdfrotParams& p, const SurfaceFrame& frame, const dvec3& wi, const dvec3& wo);

// L_o = Σ_k E_k(n) · f(lifted ξ_k, ω_o) for n·ω_o > 0, else 0.
dvec3 mdfrot_radiance(const MdfrotParams& p, const SurfaceFrame& frame, const dvec3& wo,
                      std::span<const SphericalGaussian> sgs);

}  // namespace weft
