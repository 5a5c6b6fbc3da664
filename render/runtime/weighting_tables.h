#pragma once
// The SG-convolved weighting function of seed 000 Eq. 10, baked per tangent sample t and SG
// sharpness level, each table compressed by truncated SVD:
//
//   T_{t,λ}(ξ, ω_o) = ∫_Ω G(ω_i; ξ, λ) W(t, ω_i, ω_o) dω_i / ∫_Ω G(ω_i; ξ, λ) dω_i
//
// with G(ω) = exp(λ(ω·ξ − 1)) (λ = 2/σ², docs/design.md §3), W from ClothBsdf::Point::weights (the
// one implementation, docs/design.md §2: it already carries a_j), Ω the upper hemisphere.
// Directions are in the shading point's local frame: n = +z, warp u = +x, weft v = +y. ξ and
// ω_o live on HemisphereNodeGrid (hemisphere_grid.h); ξ below the horizon is looked up at the
// nearest horizon direction (the paper tabulates ξ on the hemisphere only).
//
// Each table is stored as T ≈ U·Vᵀ, U = (ξ nodes × rank, singular values folded in),
// V = (ω_o nodes × rank), float.
#include <array>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/hemisphere_grid.h"

namespace weft {

struct CompressedTable {
  int rank = 0;
  std::vector<float> u;  // xi_nodes × rank, row-major (node-major)
  std::vector<float> v;  // wo_nodes × rank, row-major
  double norm = 0.0;     // ‖T‖_F of the uncompressed table
  double error = 0.0;    // ‖T − U·Vᵀ‖_F / ‖T‖_F (0 for an all-zero table)
};

struct WeightingTables {
  std::array<int, 2> tangent_samples{0, 0};  // N_j per thread
  std::vector<double> tilts;                 // α of each sample t, thread 0's first (radians)
  HemisphereNodeGrid xi_grid, wo_grid;
  std::vector<double> lambdas;               // sharpness levels, increasing, log-spaced
  // Samples of one thread with the same tilt have the same T (W depends on a sample only
  // through its frame), so they share one stored table: a straight thread stores one.
  std::vector<int> sample_table;             // t → index d of its distinct table
  std::vector<CompressedTable> tables;       // [d · lambdas.size() + level]

  int sample_count() const { return static_cast<int>(tilts.size()); }
  int distinct_count() const { return lambdas.empty() ? 0 : static_cast<int>(tables.size() / lambdas.size()); }
  int level_count() const { return static_cast<int>(lambdas.size()); }
  const CompressedTable& table(int t, int level) const {
    return tables[size_t(sample_table[t]) * lambdas.size() + level];
  }

  // Value of one compressed table at grid nodes (no interpolation).
  double node_value(int t, int level, int xi_node, int wo_node) const;
  // T(t, λ, ξ, ω_o): bilinear in both direction grids, linear in log λ between the two
  // nearest levels (clamped to the baked range). ξ, ω_o unit vectors in the local frame.
  double value(int t, double lambda, const glm::dvec3& xi, const glm::dvec3& wo) const;
  // The two levels value() blends for sharpness λ and the weight f of the second (level l1);
  // the GPU path takes its levels from here too.
  void level_weights(double lambda, int& l0, int& l1, double& f) const;

  std::size_t bytes() const;  // payload: the U and V factors
};

}  // namespace weft

namespace weft {

// What a bake produced, for reports: ranks and errors over all distinct (t, λ) tables.
struct TableSummary {
  int min_rank = 0, max_rank = 0;
  double mean_rank = 0.0;
  double mean_error = 0.0, max_error = 0.0;
  std::vector<std::pair<int, int>> rank_histogram;  // (rank, how many tables), increasing rank
};
TableSummary summarize(const WeightingTables& tables);

}  // namespace weft
