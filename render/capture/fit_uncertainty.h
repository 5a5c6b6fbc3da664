#pragma once
// The fabric fit's parameter covariance at its optimum, in the fit's own (logistic z) units:
// the Gauss–Newton covariance (JᵀJ)⁻¹·s² of the plain least-squares problem, s² its residual
// variance, plus what a systematic error in the photos' level would do. The residuals cannot show
// the latter: an error common to every cell (the response's scale, the ball's colour) moves the
// fit without leaving a residual, and a sparse thread's colour, a small difference between the
// swatch and its dominant thread, moves the most. Propagated linearly: a level error ε_c in
// channel c shifts the parameters by −(JᵀJ)⁻¹Jᵀ·∂f/∂ε_c.
#include <array>

#include <Eigen/Dense>

namespace weft {

// J: the residuals' Jacobian (rows as f); f: the residuals; level_columns[c]: ∂f/∂ε_c, the
// residuals' change per unit relative change of channel c of every observation; level_sigma: 1σ
// of that relative change.
Eigen::MatrixXd fit_covariance(const Eigen::MatrixXd& J, const Eigen::VectorXd& f, const std::array<Eigen::VectorXd, 3>& level_columns,
                               double level_sigma);

}  // namespace weft
