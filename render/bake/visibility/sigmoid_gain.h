#pragma once
// The triple product of two circular Gaussians and the linear visibility V' (seed 000 §3.2,
// Eq. 12–14), the 4D function H(σ_l, σ'_l, d, ∇d) it reduces to, and the sigmoid gain table
// κ(σ_l, σ'_l, ∇d) that replaces H at run time:  H ≈ 1 / (1 + exp(−κ·d)).
//
// Circular Gaussian (seed 000 Eq. 2): g^c(x; μ, σ) = exp(2/σ² · (cos(x − μ) − 1)).
// All integrals run over the paper's square [−π/2, π/2]² in (θ_i, φ_i). g^c itself and Eq. 13
// (the Gaussian closed form of the unoccluded pair integral) live in core/circular_gaussian.h;
// core's linear_visibility_ratio is H for untruncated Gaussians, the limit this file's exact H
// (truncated circular Gaussians, what the paper fits its sigmoid to) tends to for narrow lobes.
//
// The table and its lookup, what the runtime reads, are in runtime/sigmoid_gain_table.h.
//
// H is computed here by quadrature that is exact to ~1e−9: one axis is integrated with
// Gauss–Legendre panels, the other in closed form through a tabulated cumulative integral of
// g^c (cubic Hermite on 4096 intervals, using the exact derivative g^c).
#include <cmath>
#include <functional>
#include <vector>

#include "runtime/sigmoid_gain_table.h"

namespace weft {

// Cumulative integral C(x) = ∫_{−π/2}^{x} g^c(t; 0, σ) dt on [−π/2, π/2] (clamped outside).
class CircularGaussianCdf {
 public:
  explicit CircularGaussianCdf(double sigma);
  double operator()(double x) const;
  double total() const { return cumulative_.back(); }
  double sigma() const { return sigma_; }

 private:
  double sigma_;
  double step_;
  std::vector<double> cumulative_;
};

// ∫_a^b g^c(x; μ, σ) dx for any a ≤ b (Gauss–Legendre panels no wider than σ/4).
double integrate_circular_gaussian(double a, double b, double mu, double sigma);

// H(σ_l, σ'_l, d, ∇d) (the latter factor of Eq. 12):
//   ∫∫ g^c(θ;0,σ_l) g^c(φ;0,σ') V'(θ,φ) dθ dφ / ∫∫ g^c(θ;0,σ_l) g^c(φ;0,σ') dθ dφ,
// with V'(θ, φ) = [∂d/∂θ·θ + ∂d/∂φ·φ + d > 0] (the means are moved to the origin, so the
// linear visibility is expressed relative to them). Quadrature, no approximation of g^c.
double occluded_ratio_h(const CircularGaussianCdf& theta_cdf, const CircularGaussianCdf& phi_cdf,
                        double d, double grad_theta, double grad_phi);
double occluded_ratio_h(double sigma_l, double sigma_prime, double d, double grad_theta,
                        double grad_phi);

// The triple product I (seed 000, the integral before Eq. 12) by quadrature for a linear
// visibility V'(θ, φ) = [a·θ + b·φ + c > 0] in absolute angles:
//   ∫∫ g^c(θ; θ_l, σ_l) g^c(φ; φ_k, σ') V' dθ dφ over [−π/2, π/2]².
double triple_product_linear_visibility(double theta_l, double phi_k, double sigma_l,
                                        double sigma_prime, double a, double b, double c);
// ∫∫ g^c(θ; θ_l, σ_l) g^c(φ; φ_k, σ') over [−π/2, π/2]² (no visibility) by quadrature: the
// quantity Eq. 13 approximates (core's circular_gaussian_pair_integral).
double circular_gaussian_pair_quadrature(double theta_l, double phi_k, double sigma_l,
                                       double sigma_prime);

// Least-squares gain for one (σ_l, σ', gradient direction β): minimises
// Σ (sigmoid(κ d_i) − H(d_i))² over d_i uniform in [−4s, 4s], s the Gaussian spread of the
// product along ∇d. Reports the max |sigmoid − H| over d ∈ [−π, π] (dense).
struct SigmoidFit {
  double kappa = 0;
  double max_error = 0;  // against H by quadrature, over d ∈ [−π, π]
  double rms_error = 0;  // over the fit samples
};
SigmoidFit fit_sigmoid_gain(const CircularGaussianCdf& theta_cdf,
                            const CircularGaussianCdf& phi_cdf, double beta);

// The table κ(σ_l, σ'_l, β) of runtime/sigmoid_gain_table.h, every cell fitted (OpenMP over
// cells). `progress(done, total)` may be empty. Throws std::invalid_argument on a bad spec.
SigmoidGainTable fit_sigmoid_gain_table(const SigmoidGainTableSpec& spec,
                                        const std::function<void(int, int)>& progress = {});

// Seed 000's error analysis of Eq. 12 with the half-plane visibility V = [θ > 0]: RMSE over
// means (θ_l, φ_k) on an n × n grid of cell centres in [−π/2, π/2]² between the true I and
//   eq12_exact:  exact ∫∫ g^c g^c  × H           (only the "move the means to 0" step of Eq. 12)
//   eq12_eq13:   Eq. 13's Gaussian ∫∫ g g × H     (Eq. 12 as evaluated at run time)
struct Eq12Errors {
  double rmse_eq12_exact = 0;
  double rmse_eq12_eq13 = 0;
};
Eq12Errors eq12_half_plane_errors(double sigma_l, double sigma_prime, int n);

}  // namespace weft
