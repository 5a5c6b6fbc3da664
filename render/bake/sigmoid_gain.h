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
// H is computed here by quadrature that is exact to ~1e−9: one axis is integrated with
// Gauss–Legendre panels, the other in closed form through a tabulated cumulative integral of
// g^c (cubic Hermite on 4096 intervals, using the exact derivative g^c).
#include <cmath>
#include <functional>
#include <vector>

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

// s = sqrt((σ_l²·∂d/∂θ² + σ'²·∂d/∂φ²) / (2|∇d|²)): the standard deviation along ∇d of
// g(θ;0,σ_l)·g(φ;0,σ') (each Gaussian exp(−x²/σ²) has variance σ²/2). Without truncation
// H = Φ(d/(|∇d|·s)), so κ ≈ 1.702/s; the table stores κ·s.
double gaussian_spread(double sigma_l, double sigma_prime, double grad_theta, double grad_phi);

// The sigmoid of Eq. 14.
inline double sigmoid(double kappa, double d) { return 1.0 / (1.0 + std::exp(-kappa * d)); }

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

// The 3D table κ(σ_l, σ'_l, β), β = atan2(|∂d/∂φ|, |∂d/∂θ|) ∈ [0, π/2]: H depends on the
// gradient only through its direction up to the sign of each component (g^c is even and the
// domain symmetric), and on its length only as d/|∇d|. σ axes are logarithmic.
struct SigmoidGainTableSpec {
  // Paper: 32 × 32 × 64. Measured here (2-core VM): 8×8×33 keeps the interpolated sigmoid
  // within 0.0097 of H at random off-node arguments; β is the axis that needs samples.
  int sigma_l_count = 12, sigma_prime_count = 12, beta_count = 33;
  // The paper's σ range is 1/(16√2)..1/√2; σ_l of a sharp lobe can be smaller. Above ~0.75
  // the square [−π/2, π/2] truncates g^c so much that no sigmoid stays within 0.01 of H
  // (measured: 0.0099 at σ = 0.75, 0.022 at σ = 1), so the table stops at 1/√2.
  double sigma_min = 1.0 / 64, sigma_max = 0.70710678118654752;
};
class SigmoidGainTable {
 public:
  // Fits every cell (OpenMP over cells). `progress(done, total)` may be empty.
  static SigmoidGainTable fit(const SigmoidGainTableSpec& spec,
                              const std::function<void(int, int)>& progress = {});
  // A table read back from storage (a bundle): the spec and its normalised gains, as
  // normalized_gains() gave them. Throws std::invalid_argument on a size mismatch or a
  // non-finite or non-positive gain.
  static SigmoidGainTable from_gains(const SigmoidGainTableSpec& spec, std::vector<float> gains,
                                     double max_fit_error);
  // κ at any (σ_l, σ', ∇d): trilinear interpolation of the normalised gain κ·s in
  // (log σ_l, log σ', β), divided by s(σ_l, σ', ∇d) of the actual arguments (gaussian_spread).
  // κ·s stays near 1.70 everywhere (the logistic–probit constant; it drifts only where the
  // square truncates wide Gaussians), so interpolating it is far more accurate than
  // interpolating κ, which changes by 30× across β when σ_l ≪ σ'. σ outside the table is
  // clamped to its range for κ·s only.
  double kappa(double sigma_l, double sigma_prime, double grad_theta, double grad_phi) const;
  // Eq. 14 with ∇d folded in: 1 / (1 + exp(−κ · d / |∇d|)).
  double h(double sigma_l, double sigma_prime, double d, double grad_theta,
           double grad_phi) const;

  const SigmoidGainTableSpec& spec() const { return spec_; }
  // The stored normalised gains κ·s, [σ_l][σ'][β] row-major (what a GPU texture holds).
  const std::vector<float>& normalized_gains() const { return kappa_; }
  double max_fit_error() const { return max_fit_error_; }      // worst cell, at its nodes
  double sigma_l_at(int i) const;
  double sigma_prime_at(int j) const;
  double beta_at(int k) const;

 private:
  SigmoidGainTableSpec spec_;
  std::vector<float> kappa_;
  double max_fit_error_ = 0;
};

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
