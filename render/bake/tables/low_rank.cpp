#include "bake/tables/low_rank.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Dense>

namespace weft {

namespace {
using MatrixF = Eigen::MatrixXf;
using MatrixD = Eigen::MatrixXd;

MatrixF orthonormal_basis(const MatrixF& y) {
  Eigen::HouseholderQR<MatrixF> qr(y);
  return qr.householderQ() * MatrixF::Identity(y.rows(), y.cols());
}

// Smallest r with ‖A‖² − Σ_{i≤r} s_i² ≤ target², or -1 when the given s do not reach it.
int rank_for(const Eigen::VectorXd& s, double norm2, double target2) {
  double kept = 0.0;
  for (int r = 0; r <= s.size(); ++r) {
    if (norm2 - kept <= target2) return r;
    if (r < s.size()) kept += s[r] * s[r];
  }
  return -1;
}
}  // namespace

LowRankFactors truncated_svd(const float* data, int rows, int cols, const LowRankOptions& options) {
  const Eigen::Map<const MatrixF> a(data, rows, cols);
  LowRankFactors out;
  out.rows = rows;
  out.cols = cols;
  const double norm2 = a.cast<double>().squaredNorm();
  out.norm = std::sqrt(norm2);
  const int full = std::min(rows, cols);
  const int cap = options.max_rank > 0 ? std::min(options.max_rank, full) : full;
  if (norm2 == 0.0 || !std::isfinite(norm2)) return out;  // rank 0 represents zero exactly
  const double target2 = options.relative_error * options.relative_error * norm2;

  std::mt19937 rng(options.seed);
  std::normal_distribution<float> normal;
  constexpr int kOversample = 8;
  int width = std::max(1, options.initial_width);
  while (true) {
    const int k = std::min(full, width + kOversample);
    MatrixF q;
    if (k >= full) {
      q = MatrixF::Identity(rows, std::min(rows, cols));
      if (rows > cols) q = orthonormal_basis(a);  // range of A itself
    } else {
      MatrixF omega(cols, k);
      for (int i = 0; i < omega.size(); ++i) omega.data()[i] = normal(rng);
      q = orthonormal_basis(a * omega);
      // One power iteration sharpens the basis toward the leading singular vectors.
      q = orthonormal_basis(a * orthonormal_basis(a.transpose() * q));
    }
    const MatrixD b = (q.transpose() * a).cast<double>();
    // B is only k × cols (k ≤ cap + oversampling): one-sided Jacobi after a QR is exact and fast
    // here, and compiles in a fraction of BDCSVD's time.
    Eigen::JacobiSVD<MatrixD> svd(b, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd s = svd.singularValues();
    int r = rank_for(s, norm2, target2);
    const bool resolved = r >= 0 && (r <= width || k >= full);
    if (resolved || k >= full || width >= cap) {
      if (r < 0 || r > cap) r = std::min<int>(cap, s.size());
      double kept = 0.0;
      for (int i = 0; i < r; ++i) kept += s[i] * s[i];
      out.rank = r;
      out.error = std::sqrt(std::max(0.0, norm2 - kept) / norm2);
      const MatrixD us = q.cast<double>() * svd.matrixU().leftCols(r) * s.head(r).asDiagonal();
      const MatrixD v = svd.matrixV().leftCols(r);
      out.u.resize(size_t(rows) * r);
      out.v.resize(size_t(cols) * r);
      for (int i = 0; i < rows; ++i)
        for (int j = 0; j < r; ++j) out.u[size_t(i) * r + j] = float(us(i, j));
      for (int i = 0; i < cols; ++i)
        for (int j = 0; j < r; ++j) out.v[size_t(i) * r + j] = float(v(i, j));
      return out;
    }
    width *= 2;
  }
}

}  // namespace weft
