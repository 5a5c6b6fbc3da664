#pragma once
// The two matrix halves of the weighting-table bake (weighting_bake.h), exposed so the
// error-target selection can probe a subset of ξ without a full bake.
#include <functional>
#include <span>
#include <vector>

#include "bake/hemisphere_grid.h"
#include "core/cloth_bsdf.h"

namespace weft {

// W(t, ω_i, ω_o) for every tangent sample t on (ω_i cell grid) × (given ω_o directions).
struct WeightGrid {
  HemisphereCellGrid wi;
  int wo_count = 0;
  std::vector<std::vector<float>> w;  // [t]: wi.size() × wo_count, column-major (ω_i fastest)

  int samples() const { return static_cast<int>(w.size()); }
  // The same function on the grid with half the cells per side (wi.n must be even): each
  // coarse cell is exactly four fine cells of equal solid angle, so W is their mean.
  WeightGrid coarsened() const;
};

// `progress(done, total)` is called from the calling thread as ω_o columns finish.
WeightGrid evaluate_weight_grid(const ClothBsdf& bsdf, int wi_n, std::span<const glm::dvec3> wo,
                                const std::function<void(int, int)>& progress = {});

// G[ξ, ω_i] = exp(λ(ξ·ω_i − 1)) / Σ_i exp(λ(ξ·ω_i − 1)): the discrete Eq. 10 weights (equal
// cells, so the solid angle cancels). (ξ count × wi.size()), column-major.
struct SgKernel {
  int rows = 0, cols = 0;
  std::vector<float> g;
};
SgKernel sg_kernel(const HemisphereCellGrid& wi, std::span<const glm::dvec3> xi, double lambda);

// T_{t,λ} = G · W_t: (kernel rows × wo_count), column-major.
std::vector<float> convolve_weights(const WeightGrid& grid, int t, const SgKernel& kernel);

}  // namespace weft
