#pragma once
// The two matrix halves of the weighting-table bake (weighting_bake.h), exposed so the
// error-target selection can probe a subset of ξ without a full bake.
#include <functional>
#include <span>
#include <vector>

#include "runtime/hemisphere_grid.h"
#include "core/cloth_bsdf.h"

namespace weft {

// W(t, ω_i, ω_o) for every tangent sample t on (ω_i node grid) × (given ω_o directions).
// Nodes, not cells: the outermost samples lie on the horizon, so interpolating W never
// extrapolates there (where a sharp lobe on the horizon sees only a thin band of W).
struct WeightGrid {
  HemisphereNodeGrid wi;
  int wo_count = 0;
  std::vector<std::vector<float>> w;  // [t]: wi.size() × wo_count, column-major (ω_i fastest)

  int samples() const { return static_cast<int>(w.size()); }
};

// `progress(done, total)` is called from the calling thread as ω_o columns finish.
WeightGrid evaluate_weight_grid(const ClothBsdf& bsdf, int wi_n, std::span<const glm::dvec3> wo,
                                const std::function<void(int, int)>& progress = {});

// The discrete Eq. 10 weights acting on W's samples. The lobe is integrated on a quadrature
// cell grid of `quadrature_n`² cells (equal solid angle, so it cancels):
//   G[ξ, c] = exp(λ(ξ·ω_c − 1)) / Σ_c exp(λ(ξ·ω_c − 1)),
// and W at each quadrature cell is the bilinear interpolation (in the square) of W's samples
// at the `wi` nodes. Folding that interpolation into the kernel, G_eff = G · P, resolves a
// sharp lobe with fine cells while W, which varies on the scale of the 20° masking lobe, is
// evaluated only on the coarser node grid. quadrature_n = 0 means wi.n cells.
// (ξ count × wi.size()), column-major.
struct SgKernel {
  int rows = 0, cols = 0;
  std::vector<float> g;
};
SgKernel sg_kernel(const HemisphereNodeGrid& wi, std::span<const glm::dvec3> xi, double lambda, int quadrature_n = 0);

// T_{t,λ} = G · W_t: (kernel rows × wo_count), column-major.
std::vector<float> convolve_weights(const WeightGrid& grid, int t, const SgKernel& kernel);
// Several samples at once, G · [W_{t_0} … W_{t_k}] (all samples when `samples` is empty):
// (kernel rows × wo_count·k), column-major, one column block per listed sample.
std::vector<float> convolve_all_weights(const WeightGrid& grid, const SgKernel& kernel,
                                        std::span<const int> samples = {});

}  // namespace weft
