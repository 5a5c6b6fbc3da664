// The fit's covariance against a straight line fitted by least squares, whose covariance is known
// in closed form, and against a pure scale y = a·x, which a level error ε moves by exactly a·ε
// (two independent such errors in quadrature).
#include <gtest/gtest.h>

#include <cmath>

#include "capture/fit_uncertainty.h"

TEST(CaptureFitUncertainty, LineFitMatchesTheClosedForm) {
  // y = a·x + b at x = 0..9, unit residual scale; residuals ±0.1 alternating.
  const int n = 10;
  Eigen::MatrixXd J(n, 2);
  Eigen::VectorXd f(n);
  double sx = 0, sxx = 0;
  for (int i = 0; i < n; ++i) {
    J(i, 0) = i;
    J(i, 1) = 1;
    f[i] = i % 2 ? 0.1 : -0.1;
    sx += i;
    sxx += i * i;
  }
  const Eigen::MatrixXd cov = weft::fit_covariance(J, f, {});
  const double s2 = n * 0.01 / (n - 2), det = n * sxx - sx * sx;
  EXPECT_NEAR(cov(0, 0), s2 * n / det, 1e-9);
  EXPECT_NEAR(cov(1, 1), s2 * sxx / det, 1e-9);
  EXPECT_NEAR(cov(0, 1), -s2 * sx / det, 1e-9);
}

TEST(CaptureFitUncertainty, LevelErrorMovesAScaleByItsShare) {
  // y = a·x with a = 0.6 in the red channel only, a perfect fit: no residual, so the covariance is
  // the level term alone, σ_a = a·σ_level.
  const int n = 8;
  const double a = 0.6, sigma = 0.02;
  Eigen::MatrixXd J(n, 1);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  std::array<Eigen::VectorXd, 3> level{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  for (int i = 0; i < n; ++i) {
    const double x = 1 + i;
    J(i, 0) = x;              // r = a·x − y
    level[0][i] = -(a * x);   // y → y·(1 + ε)
  }
  const Eigen::MatrixXd cov = weft::fit_covariance(J, f, {{level, sigma}});
  EXPECT_NEAR(std::sqrt(cov(0, 0)), a * sigma, 1e-9);
  // A second, independent error of the same effect at 3σ: the two add in quadrature.
  const Eigen::MatrixXd both = weft::fit_covariance(J, f, {{level, sigma}, {level, 3 * sigma}});
  EXPECT_NEAR(std::sqrt(both(0, 0)), a * sigma * std::sqrt(10.0), 1e-9);
}
