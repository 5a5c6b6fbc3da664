#pragma once
// The fabric fit's parameter covariance at its optimum, in the fit's own (logistic z) units:
// the Gauss–Newton covariance (JᵀJ)⁻¹·s² of the plain least-squares problem, s² its residual
// variance, plus what systematic errors would do: in the photos' level, and in the lighting's
// shape. The residuals cannot show them: an error common to every cell (the response's scale,
// the ball's colour, how much of its light it puts high or low) moves the fit without leaving a
// residual, and a sparse thread's colour, a small difference between the swatch and its dominant
// thread, moves the most; so does an albedo against its thread's k_d. Propagated linearly: an
// error ε shifts the parameters by −(JᵀJ)⁻¹Jᵀ·∂f/∂ε.
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace weft {

// A systematic error the residuals cannot show: ∂f/∂ε for each of its components ε (rows as f),
// and 1σ of each component.
struct SystematicError {
  std::array<Eigen::VectorXd, 3> columns;
  double sigma = 0;
};

// J: the residuals' Jacobian (rows as f); f: the residuals; `systematic`: each error's columns,
// e.g. the level's ∂f/∂ε_c (the residuals' change per unit relative change of channel c of every
// observation), or the lighting's shape.
Eigen::MatrixXd fit_covariance(const Eigen::MatrixXd& J, const Eigen::VectorXd& f, const std::vector<SystematicError>& systematic);

}  // namespace weft
