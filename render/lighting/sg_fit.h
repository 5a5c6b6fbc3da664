#pragma once
// Fitting K spherical Gaussians to an environment map (DESIGN.md §3, `weft fit`).
//
// Objective: the solid-angle weighted L2 error of the radiance over the sphere,
//   Σ_i Ω_i ‖L(d_i) − Σ_k μ_k exp(λ_k(d_i·ξ_k − 1))‖²,
// on the map resampled (area-weighted) to a fit grid, with μ_k ≥ 0 (RGB) and λ_k in
// [min_sharpness, max_sharpness]. Steps, all deterministic:
//  1. seeds: greedy matching pursuit on the residual — the (ξ, λ) lobe with the largest
//     non-negative projection on what is still unexplained, over the texel centres of a
//     32×16 grid plus the residual's brightest fit-grid texel; after each addition all
//     amplitudes are re-solved by NNLS;
//  2. Levenberg–Marquardt on all parameters (axis by tangent-plane steps, log λ, μ), with
//     bounds by projection;
//  3. a final NNLS of the amplitudes for the refined lobes.
// The fit grid is first blurred with the narrowest lobe it resolves (λ_b = (H/π)², σ = one
// texel), power-preserving, so that sources smaller than a lobe keep their power; fitted lobes
// are then sharpened back (λ → λλ_b/(λ_b − λ), power kept), up to max_sharpness.
// A warm start (previous frame's SGs) skips most of step 1 and needs few LM iterations.
#include <span>

#include "core/spherical_gaussian.h"
#include "lighting/env_map.h"

namespace weft {

struct SgFitOptions {
  int count = 10;                // K
  int grid_width = 128;          // fit grid width (height = width / 2)
  double min_sharpness = 0.1;    // λ bounds; an SG with λ = 0.1 is nearly a constant
  double max_sharpness = 1000.0; // σ ≈ 1/√λ ≈ 1.8°: where sources smaller than that end up
  int max_iterations = 40;       // LM iterations (a warm start needs fewer)
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
