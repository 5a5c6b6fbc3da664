#pragma once
// Truncated SVD of one table to an error target, fast enough for dozens of 2304×2304 tables:
// a randomised range finder (Halko, Martinsson & Tropp 2011) with one power iteration, widened
// until the target is met, then an exact small SVD of the projected matrix. The error of the
// stored rank-r factors is exact, not estimated: with Q orthonormal and B = QᵀA,
// ‖A − Q·B_r‖²_F = ‖A‖²_F − Σ_{i≤r} s_i².
#include <vector>

namespace weft {

struct LowRankFactors {
  int rows = 0, cols = 0, rank = 0;
  std::vector<float> u;  // rows × rank, row-major, singular values folded in
  std::vector<float> v;  // cols × rank, row-major
  double norm = 0.0;     // ‖A‖_F
  double error = 0.0;    // ‖A − U·Vᵀ‖_F / ‖A‖_F
};

struct LowRankOptions {
  double relative_error = 0.01;  // target on ‖A − U·Vᵀ‖_F / ‖A‖_F
  int max_rank = 0;              // 0: no cap besides min(rows, cols)
  int initial_width = 32;        // first range-finder width; doubled while the target is missed
  unsigned seed = 1;
};

// A is column-major rows × cols (as Eigen stores it). Returns the smallest rank whose exact
// error meets the target among the ranks the range finder resolves (an upper bound on the
// true minimum rank, equal to it when the spectrum decays, as these tables' do).
LowRankFactors truncated_svd(const float* a_col_major, int rows, int cols, const LowRankOptions& options);

}  // namespace weft
