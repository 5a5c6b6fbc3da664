#pragma once
// Circular Gaussians and the SG → circular-Gaussian machinery of seed 000 §3.1–3.2 (and seed 001
// §3.1, appendix Eq. 17). Symbols follow seed 000 §2.2:
//   g^c(x;μ,σ) = exp((2/σ²)(cos(x−μ) − 1))   (Eq. 2)   circular_gaussian
//   g(x;μ,σ)   = exp(−(x−μ)²/σ²)             (Eq. 3)   bandwidth_gaussian
//   g^u(x;μ,σ) = g(x;μ,σ)/(√π σ)              (Eq. 4)   normalized_bandwidth_gaussian
// σ is a bandwidth, not a standard deviation: g(x;0,σ) has standard deviation σ/√2, so docs/design.md's
// N(x;γ) (Table II's γ, a standard deviation) is g^u(x;0,√2·γ). Angles in radians.
#include <limits>

#include "core/microcylinder.h"
#include "core/spherical_gaussian.h"

namespace weft {

double circular_gaussian(double x, double mu, double sigma);            // g^c
double bandwidth_gaussian(double x, double mu, double sigma);           // g
double normalized_bandwidth_gaussian(double x, double mu, double sigma); // g^u
// Seed bandwidth of a Table II standard deviation γ: √2·γ.
double seed_bandwidth_from_std_dev(double gamma);

// α·g^c(x; μ, σ). σ = +∞ is the constant α (what a product of opposed equal lobes becomes).
struct ScaledCircularGaussian {
  double alpha = 1.0;  // α
  double mu = 0.0;     // μ
  double sigma = 1.0;  // σ
  double operator()(double x) const { return alpha * circular_gaussian(x, mu, sigma); }
};

// Seed 001 appendix Eq. 17: g^c(x;μ₁,σ₁)·g^c(x;μ₂,σ₂) = α·g^c(x;μ₃,σ₃), exactly. With κ = 2/σ²,
// κ₁cos(x−μ₁) + κ₂cos(x−μ₂) = κ₃cos(x−μ₃) by the sum of cosines, where κ₃e^{iμ₃} = κ₁e^{iμ₁} + κ₂e^{iμ₂};
// so σ₃ = √(2/κ₃), μ₃ = arg(κ₁e^{iμ₁} + κ₂e^{iμ₂}) and α = exp(κ₃ − κ₁ − κ₂)
// (= exp(−4κ₁κ₂ sin²((μ₁−μ₂)/2)/(κ₃ + κ₁ + κ₂)), the form evaluated). Scales multiply.
ScaledCircularGaussian product(const ScaledCircularGaussian& a, const ScaledCircularGaussian& b);

// Seed 000 Eq. 11: an SG lobe G_k in a thread frame (t, n', b) of docs/design.md §2, with θ, φ the fiber
// angles of fiber_angles(), splits as G_k(ω_i) = g^c(θ_i;θ_k,σ_k)·g^c(φ_i;φ_k,σ'_k) where (θ_k, φ_k)
// are the angles of ξ_k and σ'_k = σ_k/√(cosθ_i cosθ_k). With σ'_k taken at the true θ_i this is
// exact (ω·ξ − 1 = (cos(θ_i−θ_k) − 1) + cosθ_i cosθ_k (cos(φ_i−φ_k) − 1)); the approximation the
// paper makes is to freeze σ'_k at one θ (θ_l in Eq. 13) so the two factors separate. That is good
// near the thread frame's equator (θ ≈ 0, where cos θ is flat) and degrades towards its poles.
// Measured (tests/core/sg_math_test.cpp; L1 error over the sphere relative to ∫G, σ' frozen at θ_k):
// ≈ 0.13·σ_k² with ξ_k on the equator (0.026, 0.0025, 0.00025 for λ = 10, 100, 1000); first order
// in σ_k·tanθ_k away from it: 0.0073 / 0.022 / 0.072 at θ_k = 30° / 60° / 80° for λ = 1000,
// 0.072 / 0.21 / 0.38 for λ = 10.
struct SgCircularSplit {
  double theta_k = 0.0;  // θ_k
  double phi_k = 0.0;    // φ_k
  double sigma_k = 1.0;  // σ_k = √(2/λ_k)
};
SgCircularSplit split_sg(const SphericalGaussian& g, const ThreadFrame& frame);
// σ'_k = σ_k/√(cosθ cosθ_k), θ the incident longitude it is evaluated at (θ_i exactly, θ_l in Eq. 13).
double sigma_prime(double sigma_k, double theta, double theta_k);
// g^c(θ_i;θ_k,σ_k)·g^c(φ_i;φ_k,σ'_k(θ_sigma)): unit amplitude. θ_sigma = θ_i gives G_k exactly.
double evaluate_split(const SgCircularSplit& s, double theta_i, double phi_i, double theta_sigma);

// Seed 000 §3.1 / seed 001 Eq. 11: g^u(θ_h;0,γ_s) with θ_h = (θ_i+θ_o)/2 equals g(θ_i;−θ_o,2γ_s)/(√π γ_s)
// exactly; replacing g by g^c gives the circular Gaussian returned (as a function of θ_i). γ_s is the
// seed's bandwidth (seed_bandwidth_from_std_dev of Table II's γ_s). g^c ≥ g with equal peaks; the
// error grows as the square of the bandwidth. Measured over θ_i, θ_o ∈ [−π/2, π/2], max error as a
// share of the peak, for Table II standard deviations γ = 2.5° / 5° / 12° / 24° / 30° / 60°:
// 0.07 % / 0.28 % / 1.6 % / 7.5 % / 15 % / 31 %. Fine for the surface lobes; poor for the widest
// volume lobes (γ_v = 60°), where the Gaussian and circular lobes differ at the tails.
ScaledCircularGaussian longitudinal_lobe_as_circular(double theta_o, double gamma_s);

// ∫_{−π/2}^{π/2} g(x;μ,σ) dx for the Gaussian g = e^{−(x−μ)²/σ²} standing in for g^c:
// (√π σ/2)·[erf((π/2−μ)/σ) − erf((−π/2−μ)/σ)]. One factor of Eq. 13.
double gaussian_half_turn_integral(double mu, double sigma);

// Seed 000 Eq. 13: ∫∫_{[−π/2,π/2]²} g^c(θ;θ_l,σ_l) g^c(φ;φ_k,σ'_l) dθ dφ with each g^c replaced by g,
// = (π σ_l σ'_l / 4)·[erf((π/2−θ_l)/σ_l) − erf((−π/2−θ_l)/σ_l)]·[erf((π/2−φ_k)/σ'_l) − erf((−π/2−φ_k)/σ'_l)].
// Exact for g; against the circular Gaussians the error is set by the wider bandwidth: 1.6 % with
// one σ = 0.5 (the widest the paper tabulates), 3.3 % with both, measured by 2D quadrature.
double circular_gaussian_pair_integral(double theta_l, double sigma_l, double phi_k, double sigma_prime_l);

// ∫_{−π}^{π} g^c(x;μ,σ) dx = 2π e^{−κ} I₀(κ), κ = 2/σ², exactly (any μ: the whole circle). The
// scaled Bessel function e^{−κ}I₀(κ) by Abramowitz & Stegun 9.8.1–9.8.2 (relative error < 1e−6); → √π σ for
// narrow lobes (the Gaussian's integral), → 2π as σ → ∞. iwasaki.glsl evaluates the same polynomial.
double circular_gaussian_circle_integral(double sigma);

// The visibility ratio H(σ_l, σ'_l, d, ∇d) of seed 000 Eq. 12–14 for the linear visibility
// V' = [∂d/∂θ·(θ−θ_l) + ∂d/∂φ·(φ−φ_k) + d > 0], with the circular Gaussians replaced by Gaussians over
// the whole plane. Then ∂d/∂θ·(θ−θ_l) + ∂d/∂φ·(φ−φ_k) is normal with variance (d_θ²σ_l² + d_φ²σ'_l²)/2,
// so H = ½ erfc(−d / √(d_θ²σ_l² + d_φ²σ'_l²)) in closed form (the paper fits a sigmoid to a table).
// A zero gradient is a step in d (½ at d = 0).
double linear_visibility_ratio(double sigma_l, double sigma_prime_l, double d, double d_dtheta, double d_dphi);

// Seed 000 Eq. 12 with the two closed forms above: the triple product I of g^c(θ;θ_l,σ_l),
// g^c(φ;φ_k,σ'_l) and V' over [−π/2,π/2]², ≈ circular_gaussian_pair_integral · linear_visibility_ratio.
// Against 2D quadrature with V = [θ > 0] and means uniform over the square (seed 000 §4's check),
// RMSE 0.011 / 0.0015 / 0.00035 / 0.0019 / 0.00044 for (σ_l, σ'_k) = (½,½) / (½,⅛) / (½,1/32) /
// (⅛,½) / (1/32,½): at most 2.5 % of the unoccluded integral, mostly Eq. 13's Gaussian replacement.
double visible_pair_integral(double theta_l, double sigma_l, double phi_k, double sigma_prime_l, double d,
                             double d_dtheta, double d_dphi);

}  // namespace weft
