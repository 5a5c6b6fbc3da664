#pragma once
// The sigmoid gain table κ(σ_l, σ'_l, ∇d) of seed 000 §3.2 (Eq. 14) and its lookup: the
// occluded share H of an SG lobe against the linear visibility V' ≈ 1 / (1 + exp(−κ·d)).
// Fitted offline (render/bake/visibility/sigmoid_gain.h, which also holds H itself); read from a bundle.
#include <cmath>
#include <vector>

namespace weft {

// s = sqrt((σ_l²·∂d/∂θ² + σ'²·∂d/∂φ²) / (2|∇d|²)): the standard deviation along ∇d of
// g(θ;0,σ_l)·g(φ;0,σ') (each Gaussian exp(−x²/σ²) has variance σ²/2). Without truncation
// H = Φ(d/(|∇d|·s)), so κ ≈ 1.702/s; the table stores κ·s.
double gaussian_spread(double sigma_l, double sigma_prime, double grad_theta, double grad_phi);

// The sigmoid of Eq. 14.
inline double sigmoid(double kappa, double d) { return 1.0 / (1.0 + std::exp(-kappa * d)); }

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
  // A table from its spec and normalised gains, as normalized_gains() gives them (a bundle's,
  // or fit_sigmoid_gain_table's in render/bake/visibility/sigmoid_gain.h). Throws std::invalid_argument
  // on a size mismatch or a non-finite or non-positive gain.
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

}  // namespace weft
