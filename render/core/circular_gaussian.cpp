#include "core/circular_gaussian.h"

#include <cmath>
#include <numbers>

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;
// κ = 2/σ², the concentration multiplying cos(x − μ); 0 for σ = ∞.
double concentration(double sigma) { return 2.0 / (sigma * sigma); }
}  // namespace

double circular_gaussian(double x, double mu, double sigma) {
  // cos(x−μ) − 1 = −2 sin²((x−μ)/2): keeps precision for narrow lobes near their peak.
  const double s = std::sin(0.5 * (x - mu));
  return std::exp(-2.0 * concentration(sigma) * s * s);
}

double bandwidth_gaussian(double x, double mu, double sigma) {
  const double u = (x - mu) / sigma;
  return std::exp(-u * u);
}

double normalized_bandwidth_gaussian(double x, double mu, double sigma) {
  return bandwidth_gaussian(x, mu, sigma) / (std::sqrt(kPi) * sigma);
}

double seed_bandwidth_from_std_dev(double gamma) { return std::numbers::sqrt2 * gamma; }

ScaledCircularGaussian product(const ScaledCircularGaussian& a, const ScaledCircularGaussian& b) {
  const double k1 = concentration(a.sigma), k2 = concentration(b.sigma);
  const double c = k1 * std::cos(a.mu) + k2 * std::cos(b.mu);
  const double s = k1 * std::sin(a.mu) + k2 * std::sin(b.mu);
  const double k3 = std::hypot(c, s);
  const double half = std::sin(0.5 * (a.mu - b.mu));
  const double denom = k3 + k1 + k2;
  ScaledCircularGaussian p;
  p.alpha = a.alpha * b.alpha * (denom > 0.0 ? std::exp(-4.0 * k1 * k2 * half * half / denom) : 1.0);
  p.mu = k3 > 0.0 ? std::atan2(s, c) : a.mu;
  p.sigma = k3 > 0.0 ? std::sqrt(2.0 / k3) : std::numeric_limits<double>::infinity();
  return p;
}

SgCircularSplit split_sg(const SphericalGaussian& g, const ThreadFrame& frame) {
  const FiberAngles a = fiber_angles(frame, g.axis);
  return {a.theta, a.phi, sg_bandwidth(g.sharpness)};
}

double sigma_prime(double sigma_k, double theta, double theta_k) {
  return sigma_k / std::sqrt(std::cos(theta) * std::cos(theta_k));
}

double evaluate_split(const SgCircularSplit& s, double theta_i, double phi_i, double theta_sigma) {
  return circular_gaussian(theta_i, s.theta_k, s.sigma_k) *
         circular_gaussian(phi_i, s.phi_k, sigma_prime(s.sigma_k, theta_sigma, s.theta_k));
}

ScaledCircularGaussian longitudinal_lobe_as_circular(double theta_o, double gamma_s) {
  return {1.0 / (std::sqrt(kPi) * gamma_s), -theta_o, 2.0 * gamma_s};
}

double gaussian_half_turn_integral(double mu, double sigma) {
  constexpr double h = 0.5 * kPi;
  return 0.5 * std::sqrt(kPi) * sigma * (std::erf((h - mu) / sigma) - std::erf((-h - mu) / sigma));
}

double circular_gaussian_pair_integral(double theta_l, double sigma_l, double phi_k, double sigma_prime_l) {
  return gaussian_half_turn_integral(theta_l, sigma_l) * gaussian_half_turn_integral(phi_k, sigma_prime_l);
}

double circular_gaussian_circle_integral(double sigma) {
  const double k = concentration(sigma);
  double scaled_i0;  // e^{−κ} I₀(κ)
  if (k < 3.75) {
    const double t = (k / 3.75) * (k / 3.75);
    scaled_i0 = std::exp(-k) * (1.0 + t * (3.5156229 + t * (3.0899424 + t * (1.2067492 +
                                t * (0.2659732 + t * (0.0360768 + t * 0.0045813))))));
  } else {
    const double t = 3.75 / k;
    scaled_i0 = (0.39894228 + t * (0.01328592 + t * (0.00225319 + t * (-0.00157565 + t * (0.00916281 +
                t * (-0.02057706 + t * (0.02635537 + t * (-0.01647633 + t * 0.00392377)))))))) / std::sqrt(k);
  }
  return 2.0 * kPi * scaled_i0;
}

double linear_visibility_ratio(double sigma_l, double sigma_prime_l, double d, double d_dtheta, double d_dphi) {
  const double spread = std::hypot(d_dtheta * sigma_l, d_dphi * sigma_prime_l);
  if (spread == 0.0) return d > 0.0 ? 1.0 : (d < 0.0 ? 0.0 : 0.5);
  return 0.5 * std::erfc(-d / spread);
}

double visible_pair_integral(double theta_l, double sigma_l, double phi_k, double sigma_prime_l, double d,
                             double d_dtheta, double d_dphi) {
  return circular_gaussian_pair_integral(theta_l, sigma_l, phi_k, sigma_prime_l) *
         linear_visibility_ratio(sigma_l, sigma_prime_l, d, d_dtheta, d_dphi);
}

}  // namespace weft
