#include "lighting/nnls.h"

#include <vector>

namespace weft {

Eigen::VectorXd solve_nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> free(n, false);
  const double tol = 1e-12 * (A.diagonal().cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff() + 1e-300);

  // The unconstrained minimiser over the free variables, the others held at 0.
  auto solve_free = [&](Eigen::VectorXd& z) {
    std::vector<Eigen::Index> idx;
    for (Eigen::Index i = 0; i < n; ++i)
      if (free[i]) idx.push_back(i);
    const Eigen::Index m = static_cast<Eigen::Index>(idx.size());
    Eigen::MatrixXd Af(m, m);
    Eigen::VectorXd bf(m);
    for (Eigen::Index r = 0; r < m; ++r) {
      bf(r) = b(idx[r]);
      for (Eigen::Index c = 0; c < m; ++c) Af(r, c) = A(idx[r], idx[c]);
    }
    // A tiny ridge keeps near-duplicate lobes solvable; it changes nothing measurable otherwise.
    Af.diagonal().array() += 1e-12 * (Af.diagonal().maxCoeff() + 1e-300);
    const Eigen::VectorXd zf = Af.ldlt().solve(bf);
    z.setZero(n);
    for (Eigen::Index r = 0; r < m; ++r) z(idx[r]) = zf(r);
  };

  for (int outer = 0; outer < 3 * n + 10; ++outer) {
    const Eigen::VectorXd gradient = b - A * x;  // the descent direction of the objective
    Eigen::Index best = -1;
    double best_value = tol;
    for (Eigen::Index i = 0; i < n; ++i)
      if (!free[i] && gradient(i) > best_value) best = i, best_value = gradient(i);
    if (best < 0) break;  // KKT: every bound variable has a non-positive gradient
    free[best] = true;

    for (int inner = 0; inner < 3 * n + 10; ++inner) {
      Eigen::VectorXd z;
      solve_free(z);
      bool feasible = true;
      for (Eigen::Index i = 0; i < n; ++i)
        if (free[i] && z(i) <= 0.0) feasible = false;
      if (feasible) {
        x = z;
        break;
      }
      // Step from x toward z as far as feasibility allows; the variables that hit 0 leave the set.
      double alpha = 1.0;
      for (Eigen::Index i = 0; i < n; ++i)
        if (free[i] && z(i) <= 0.0) alpha = std::min(alpha, x(i) / (x(i) - z(i)));
      x += alpha * (z - x);
      for (Eigen::Index i = 0; i < n; ++i)
        if (free[i] && x(i) <= tol) free[i] = false, x(i) = 0.0;
    }
  }
  return x.cwiseMax(0.0);
}

}  // namespace weft
