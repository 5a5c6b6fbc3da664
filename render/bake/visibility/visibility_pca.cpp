#include "bake/visibility/visibility_pca.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace weft {

namespace {

// Left singular vectors and values of X (cells × vertices), the leading `rank` of them.
// Small problems: Eigen's BDCSVD of X itself. Large ones: randomised subspace iteration
// (Halko–Martinsson–Tropp): Q = orth((X Xᵀ)^q X Ω), then the SVD of the small Qᵀ X. The basis
// is then approximate, but every error this file reports is measured for the basis it returns.
void leading_singular(const Eigen::MatrixXf& x, int rank, int exact_limit, Eigen::MatrixXf& u,
                      Eigen::VectorXd& s) {
  if (x.rows() <= exact_limit && x.cols() > 4 * x.rows()) {
    // Few cells, many vertices (a floor's 32² grids): the eigenvectors of X·Xᵀ, a cells² symmetric
    // problem, are X's left singular vectors. Jacobi on X itself costs a minute there (cells³
    // rotations a sweep); the squared condition number only blurs singular values far below
    // the ones kept, and every error reported is measured for the basis returned.
    const Eigen::MatrixXd xd = x.cast<double>();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(xd * xd.transpose());
    const Eigen::Index n = x.rows();
    u.resize(n, rank);
    s.resize(rank);
    for (int k = 0; k < rank; ++k) {  // eigenvalues ascend: the leading ones last
      u.col(k) = eig.eigenvectors().col(n - 1 - k).cast<float>();
      s[k] = std::sqrt(std::max(0.0, eig.eigenvalues()[n - 1 - k]));
    }
    return;
  }
  if (std::min(x.rows(), x.cols()) <= exact_limit) {
    // Jacobi (after a QR to the small side) rather than BDCSVD: as exact, and far cheaper to compile.
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(x.cast<double>(), Eigen::ComputeThinU);
    u = svd.matrixU().leftCols(rank).cast<float>();
    s = svd.singularValues().head(rank);
    return;
  }
  const int probe = std::min<int>(rank + 16, std::min(x.rows(), x.cols()));
  std::mt19937 rng(1234567);  // fixed: a bake is reproducible
  std::normal_distribution<float> normal;
  Eigen::MatrixXf omega(x.cols(), probe);
  for (int j = 0; j < omega.cols(); ++j)
    for (int i = 0; i < omega.rows(); ++i) omega(i, j) = normal(rng);
  auto orthonormal = [](const Eigen::MatrixXf& m) {
    Eigen::HouseholderQR<Eigen::MatrixXf> qr(m);
    return Eigen::MatrixXf(qr.householderQ() * Eigen::MatrixXf::Identity(m.rows(), m.cols()));
  };
  Eigen::MatrixXf q = orthonormal(x * omega);
  for (int iter = 0; iter < 2; ++iter) {
    const Eigen::MatrixXf w = orthonormal(x.transpose() * q);
    q = orthonormal(x * w);
  }
  const Eigen::MatrixXf b = q.transpose() * x;
  // In double: the singular values choose the term count, and float Jacobi sweeps lose the last
  // digits that the target error is measured against.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(b.cast<double>(), Eigen::ComputeThinU);
  u = q * svd.matrixU().leftCols(rank).cast<float>();
  s = svd.singularValues().head(rank);
}

}  // namespace

Eigen::VectorXf SdfPca::reconstruct(int vertex) const {
  if (vertex < 0 || vertex >= coefficients.cols())
    throw std::out_of_range("SDF PCA: no vertex " + std::to_string(vertex));
  return mean + basis * coefficients.col(vertex);
}

SdfPca fit_sdf_pca(const Eigen::MatrixXf& sdfs, const SdfPcaOptions& options) {
  if (sdfs.rows() == 0 || sdfs.cols() == 0)
    throw std::invalid_argument("SDF PCA: no SDFs to compress");
  if (!sdfs.allFinite()) throw std::invalid_argument("SDF PCA: an SDF holds NaN or infinity");
  if (!(options.target_rms_error >= 0) || options.max_terms < 0)
    throw std::invalid_argument("SDF PCA: target error must be ≥ 0 and max terms ≥ 0");
  SdfPca pca;
  const double cells = double(sdfs.rows()), vertices = double(sdfs.cols());
  pca.mean = sdfs.rowwise().mean();
  const Eigen::MatrixXf x = sdfs.colwise() - pca.mean;
  const double total = x.cast<double>().squaredNorm();
  const int rank = int(std::min<Eigen::Index>(options.max_terms, std::min(x.rows(), x.cols())));

  Eigen::MatrixXf u;
  Eigen::VectorXd s;
  if (rank > 0) leading_singular(x, rank, options.exact_svd_limit, u, s);

  // Residual with k terms: ‖X‖² − Σ_{i<k} s_i² (the coefficients are the projections).
  double captured = 0;
  int chosen = -1;
  for (int k = 0; k <= rank; ++k) {
    if (k > 0) captured += s[k - 1] * s[k - 1];
    const double rms = std::sqrt(std::max(0.0, total - captured) / (cells * vertices));
    pca.rms_error_by_terms.push_back(rms);
    if (chosen < 0 && rms <= options.target_rms_error) chosen = k;
  }
  if (chosen < 0) chosen = rank;  // target not reachable: best we computed, error says so

  pca.basis = u.leftCols(chosen);
  pca.coefficients = pca.basis.transpose() * x;
  // Measured, not predicted: what a reader of the bundle will get back.
  // Column by column: a whole residual matrix would double the memory of a large bake.
  double squared = 0, worst = 0;
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    const Eigen::VectorXd r = (x.col(v) - pca.basis * pca.coefficients.col(v)).cast<double>();
    squared += r.squaredNorm();
    worst = std::max(worst, r.cwiseAbs().maxCoeff());
  }
  pca.rms_error = std::sqrt(squared / (cells * vertices));
  pca.max_error = worst;
  return pca;
}

}  // namespace weft
