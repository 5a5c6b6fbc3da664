#include "capture/fit_uncertainty.h"

#include <algorithm>

namespace weft {

Eigen::MatrixXd fit_covariance(const Eigen::MatrixXd& J, const Eigen::VectorXd& f, const std::vector<SystematicError>& systematic) {
  const Eigen::Index n = J.cols();
  const Eigen::MatrixXd inverse = (J.transpose() * J + 1e-9 * Eigen::MatrixXd::Identity(n, n)).inverse();
  const double s2 = f.squaredNorm() / static_cast<double>(std::max<Eigen::Index>(1, J.rows() - n));
  Eigen::MatrixXd cov = inverse * s2;
  for (const SystematicError& error : systematic)
    for (const Eigen::VectorXd& column : error.columns) {
      const Eigen::VectorXd shift = -inverse * (J.transpose() * column);
      cov += error.sigma * error.sigma * shift * shift.transpose();
    }
  return cov;
}

}  // namespace weft
