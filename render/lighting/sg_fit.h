#pragma once
// Fitting K spherical Gaussians to an environment map (docs/design.md §3, `weft fit`).
//
// Objective, on the map resampled (area-weighted) to a fit grid, with μ_k ≥ 0 (RGB) and λ_k in
// [min_sharpness, max_sharpness]:
//   Σ_i Ω_i ‖L(d_i) − S(d_i)‖²  +  w ∫‖E_L(n) − E_S(n)‖² dn,     S = Σ_k μ_k exp(λ_k(d·ξ_k − 1)),
// the radiance error over the sphere plus w times the diffuse irradiance error over all normals.
// The second term is exact on bands 0..2 (Parseval: Σ_lm Â_l² (L_lm − S_lm)², Â the clamped
// cosine's coefficients), nine least-squares rows per channel beside the texels' rows; it makes
// the few lobes spend themselves on what a diffuse surface sees before the fine detail.
// Steps, all deterministic:
//  0. a compact bright source (compact_source.h: a sun, a spot lamp) gets one lobe of its own, at
//     the centroid of its power above the sky around it, with that power, λ from its spread
//     (up to max_sharpness); its texels are set to that sky and the other K − 1 lobes fit the rest;
//  1. seeds: greedy matching pursuit on the residual — the (ξ, λ) lobe with the largest
//     non-negative projection on what is still unexplained, over the texel centres of a
//     32×16 grid plus the residual's brightest fit-grid texel; after each addition all
//     amplitudes are re-solved by NNLS;
//  2. Levenberg–Marquardt on all parameters (axis by tangent-plane steps, log λ, μ), with
//     bounds by projection (hand-written: Eigen's unsupported LevenbergMarquardt has no bounds
//     and would form the full 3N × 6K Jacobian, where the channels' shared geometry lets this
//     one assemble JᵀJ from an N × 4K matrix);
//  3. a final NNLS of the amplitudes for the refined lobes.
// The fit grid is first blurred with the narrowest lobe it resolves (λ_b = (H/π)², σ = one
// texel), power-preserving, so that sources smaller than a lobe keep their power; fitted lobes
// are then sharpened back (λ → λλ_b/(λ_b − λ), power kept), up to max_sharpness.
// A warm start (previous frame's SGs) skips most of step 1 and needs few LM iterations; its lobe
// on a source found again in step 0 is replaced by the source's.
#include <span>

#include "core/spherical_gaussian.h"
#include "lighting/env_map.h"

namespace weft {

struct SgFitOptions {
  int count = 10;                // K
  int grid_width = 128;          // fit grid width (height = width / 2)
  // λ bounds. The shading tables cover 1/16..1024; lobes broader than λ ≈ 1 are the hard ones
  // to shade (docs/research/iwasaki.md) and the skies and bundled maps fit as well
  // without them (docs/bench/low_sun/fit_error.md).
  double min_sharpness = 1.0;
  double max_sharpness = 1000.0; // σ ≈ 1/√λ ≈ 1.8°: where sources smaller than that end up
  int max_iterations = 40;       // LM iterations (a warm start needs fewer)
  double irradiance_weight = 4.0;  // w of the objective's irradiance term (0: radiance only;
                                   // 1, 4, 16 measured in docs/bench/low_sun/fit_error.md)
  bool single_lobe_source = true;  // a compact bright source (a sun) gets one lobe of its own
};

struct SgFitStats {
  int iterations = 0;       // LM iterations taken
  double initial_cost = 0;  // objective after seeding (or of the warm start)
  double final_cost = 0;    // objective at the end
  double max_sharpness = 0; // the output bound used
};

// Fits options.count SGs to `map`. `initial`, when given, is the starting set (e.g. the last
// frame's fit): missing lobes are seeded greedily, surplus weakest lobes dropped. Throws
// std::invalid_argument on bad options (count < 1, grid too small, bad bounds).
SgLighting fit_sgs(const EnvMap& map, const SgFitOptions& options = {},
                   std::span<const SphericalGaussian> initial = {}, SgFitStats* stats = nullptr);

}  // namespace weft
