#pragma once
// Bakes the weighting tables T_{t,λ}(ξ, ω_o) of weighting_tables.h as matrix products:
//   1. W(t, ω_i, ω_o) on a cell grid of ω_i × the node grid of ω_o, all samples t from one
//      ClothBsdf::Point::weights call per (ω_i, ω_o) pair;
//   2. per sharpness level λ: G[ξ, ω_i] = exp(λ(ξ·ω_i − 1)) / Σ_i exp(λ(ξ·ω_i − 1)) (the cells
//      have equal solid angle, so it cancels: G's rows are the discrete Eq. 10 weights) and
//      T_{t,λ} = G · W_t, one GEMM per (t, λ);
//   3. each T_{t,λ} truncated by SVD to a relative Frobenius error target (low_rank.h).
// W is sampled on a fixed ω_i node grid; each level integrates its lobe on a quadrature grid
// fine enough for it (cell spacing √(2π)/n ≤ `cell_per_lobe` × the lobe's width 1/√λ), with W
// interpolated bilinearly from the samples and the interpolation folded into G (sg_convolution.h).
#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/weighting_tables.h"
#include "core/fabric.h"

namespace weft {

struct BakeSettings {
  std::array<int, 2> tangent_samples{3, 3};  // N_j; seed 000 Table 1 uses 6 in all for linen
  int xi_resolution = 48;                    // ξ node grid n×n (paper: 48×48)
  int wo_resolution = 48;                    // ω_o node grid n×n (paper: 48×48)
  int wi_resolution = 48;                    // ω_i nodes where W is sampled, n×n
  double cell_per_lobe = 0.75;               // quadrature cell spacing ≤ this × 1/√λ
  // λ = 2/σ²: the paper samples σ from 1/√2 to 1/(16√2) logarithmically, i.e. λ 4..1024. The
  // levels reach down to 1/16 here, below the SG fit's broadest lobe (sg_fit.h, λ = 0.1): a sky's
  // fit holds several lobes at λ ≈ 2, and T read at λ = 4 for them shades the swatch 15 % off.
  double lambda_min = 1.0 / 16.0, lambda_max = 1024.0;
  int lambda_levels = 15;                    // log-spaced, both ends included (×2 apart)
  double svd_error = 0.01;                   // per (t, λ): ‖T − T_r‖_F / ‖T‖_F ≤ this
  int max_rank = 0;                          // 0: no cap

  std::vector<double> lambdas() const;       // the levels these settings give
  // Throws std::invalid_argument naming the field when a value is unusable.
  void validate() const;
};

// fraction in [0, 1] of the whole bake, and what it is doing now.
using BakeProgress = std::function<void(double fraction, std::string_view stage)>;

struct BakeTimings {
  double weights_s = 0.0;   // W on the grid
  double convolve_s = 0.0;  // the G·W products
  double compress_s = 0.0;  // SVD truncation
};

WeightingTables bake_weighting_tables(const Fabric& fabric, const BakeSettings& settings,
                                      const BakeProgress& progress = {}, BakeTimings* timings = nullptr);

// The quadrature grid (n×n cells) a level of sharpness λ uses under `settings`.
int quadrature_resolution_for(const BakeSettings& settings, double lambda);

}  // namespace weft
