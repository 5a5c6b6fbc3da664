#include "bake/visibility/sigmoid_gain.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/circular_gaussian.h"

namespace weft {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kHalfPi = kPi / 2;

// 8-point Gauss–Legendre on [−1, 1].
constexpr double kGlX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                            0.9602898564975363};
constexpr double kGlW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                            0.1012285362903763};

// Σ over GL panels of width ≤ max_width on [a, b] of f(x) dx.
template <class F>
double gauss_legendre(double a, double b, double max_width, F&& f) {
  if (!(b > a)) return 0.0;
  const int panels = std::clamp(int(std::ceil((b - a) / max_width)), 1, 1 << 16);
  const double w = (b - a) / panels;
  double sum = 0;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * w, half = 0.5 * w;
    for (int k = 0; k < 4; ++k)
      sum += kGlW[k] * half * (f(mid - half * kGlX[k]) + f(mid + half * kGlX[k]));
  }
  return sum;
}

void check_sigma(double sigma) {
  if (!(sigma > 0) || !std::isfinite(sigma))
    throw std::invalid_argument("circular Gaussian bandwidth must be positive and finite, got " +
                                std::to_string(sigma));
}

// Where g^c(x; 0, σ) drops below e^−46 (~1e−20): nothing beyond matters.
double support_half_width(double sigma) {
  const double c = 1.0 - 23.0 * sigma * sigma;
  return c <= -1.0 ? kPi : std::acos(c);
}

}  // namespace

double integrate_circular_gaussian(double a, double b, double mu, double sigma) {
  check_sigma(sigma);
  const double reach = support_half_width(sigma);
  a = std::max(a, mu - reach);
  b = std::min(b, mu + reach);
  return gauss_legendre(a, b, sigma / 4,
                        [&](double x) { return circular_gaussian(x, mu, sigma); });
}

CircularGaussianCdf::CircularGaussianCdf(double sigma) : sigma_(sigma) {
  check_sigma(sigma);
  constexpr int kIntervals = 4096;
  step_ = kPi / kIntervals;
  cumulative_.resize(kIntervals + 1);
  cumulative_[0] = 0;
  for (int m = 0; m < kIntervals; ++m) {
    const double a = -kHalfPi + m * step_;
    cumulative_[m + 1] = cumulative_[m] + integrate_circular_gaussian(a, a + step_, 0.0, sigma);
  }
}

double CircularGaussianCdf::operator()(double x) const {
  if (x <= -kHalfPi) return 0.0;
  if (x >= kHalfPi) return cumulative_.back();
  const double u = (x + kHalfPi) / step_;
  const int m = std::min(int(u), int(cumulative_.size()) - 2);
  const double t = u - m;
  // Cubic Hermite with the exact derivative C' = g^c.
  const double x0 = -kHalfPi + m * step_;
  const double c0 = cumulative_[m], c1 = cumulative_[m + 1];
  const double d0 = circular_gaussian(x0, 0, sigma_) * step_;
  const double d1 = circular_gaussian(x0 + step_, 0, sigma_) * step_;
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * c0 + (t3 - 2 * t2 + t) * d0 + (-2 * t3 + 3 * t2) * c1 +
         (t3 - t2) * d1;
}

double occluded_ratio_h(const CircularGaussianCdf& theta_cdf, const CircularGaussianCdf& phi_cdf,
                        double d, double grad_theta, double grad_phi) {
  if (!std::isfinite(d) || !std::isfinite(grad_theta) || !std::isfinite(grad_phi))
    throw std::invalid_argument("H: d and ∇d must be finite");
  if (grad_theta == 0 && grad_phi == 0) return d > 0 ? 1.0 : (d < 0 ? 0.0 : 0.5);
  // Integrate numerically along the axis on which the visible fraction of the other axis
  // varies slowest (fewest panels), and in closed form (the cumulative table) along the other.
  const bool outer_is_theta =
      theta_cdf.sigma() * std::abs(grad_theta) <= phi_cdf.sigma() * std::abs(grad_phi);
  const CircularGaussianCdf& outer = outer_is_theta ? theta_cdf : phi_cdf;
  const CircularGaussianCdf& inner = outer_is_theta ? phi_cdf : theta_cdf;
  const double g_outer = outer_is_theta ? grad_theta : grad_phi;
  const double g_inner = outer_is_theta ? grad_phi : grad_theta;  // never 0 here
  // Visible where g_inner·y > −(d + g_outer·x): y beyond the threshold t(x).
  auto inner_visible = [&](double x) {
    const double t = -(d + g_outer * x) / g_inner;
    return g_inner > 0 ? inner.total() - inner(t) : inner(t);
  };
  const double reach = std::min(kHalfPi, support_half_width(outer.sigma()));
  std::vector<double> breaks{-reach, reach};
  if (g_outer != 0)  // t(x) = ±π/2: kinks of the inner fraction
    for (double edge : {-kHalfPi, kHalfPi}) {
      const double x = (-d - g_inner * edge) / g_outer;
      if (x > -reach && x < reach) breaks.push_back(x);
    }
  std::sort(breaks.begin(), breaks.end());
  // 8-point Gauss–Legendre is exact to ~1e−10 on a Gaussian over half its width.
  double width = outer.sigma() / 2;
  if (g_outer != 0) width = std::min(width, inner.sigma() * std::abs(g_inner / g_outer) / 2);
  double sum = 0;
  for (size_t s = 0; s + 1 < breaks.size(); ++s)
    sum += gauss_legendre(breaks[s], breaks[s + 1], width, [&](double x) {
      return circular_gaussian(x, 0, outer.sigma()) * inner_visible(x);
    });
  return std::clamp(sum / (outer.total() * inner.total()), 0.0, 1.0);
}

double occluded_ratio_h(double sigma_l, double sigma_prime, double d, double grad_theta,
                        double grad_phi) {
  return occluded_ratio_h(CircularGaussianCdf(sigma_l), CircularGaussianCdf(sigma_prime), d,
                          grad_theta, grad_phi);
}

double circular_gaussian_pair_quadrature(double theta_l, double phi_k, double sigma_l,
                                       double sigma_prime) {
  return integrate_circular_gaussian(-kHalfPi, kHalfPi, theta_l, sigma_l) *
         integrate_circular_gaussian(-kHalfPi, kHalfPi, phi_k, sigma_prime);
}

double triple_product_linear_visibility(double theta_l, double phi_k, double sigma_l,
                                        double sigma_prime, double a, double b, double c) {
  check_sigma(sigma_l);
  check_sigma(sigma_prime);
  if (a == 0 && b == 0) return c > 0 ? circular_gaussian_pair_quadrature(theta_l, phi_k, sigma_l, sigma_prime) : 0.0;
  // Visible half-line of one axis given the other: separable when one coefficient is 0.
  auto visible_part = [](double coef, double rhs, double mu, double sigma) {
    // ∫ g^c(y; μ, σ) over {y ∈ [−π/2, π/2] : coef·y > rhs}
    const double t = rhs / coef;
    return coef > 0 ? integrate_circular_gaussian(std::max(t, -kHalfPi), kHalfPi, mu, sigma)
                    : integrate_circular_gaussian(-kHalfPi, std::min(t, kHalfPi), mu, sigma);
  };
  if (b == 0)
    return visible_part(a, -c, theta_l, sigma_l) *
           integrate_circular_gaussian(-kHalfPi, kHalfPi, phi_k, sigma_prime);
  if (a == 0)
    return integrate_circular_gaussian(-kHalfPi, kHalfPi, theta_l, sigma_l) *
           visible_part(b, -c, phi_k, sigma_prime);
  // General line: θ outer (GL panels, split where the φ threshold leaves the square), φ inner.
  std::vector<double> breaks{std::max(-kHalfPi, theta_l - support_half_width(sigma_l)),
                             std::min(kHalfPi, theta_l + support_half_width(sigma_l))};
  for (double edge : {-kHalfPi, kHalfPi}) {
    const double x = (-c - b * edge) / a;
    if (x > breaks[0] && x < breaks[1]) breaks.push_back(x);
  }
  std::sort(breaks.begin(), breaks.end());
  const double width = std::min(sigma_l, sigma_prime * std::abs(b / a)) / 4;
  double sum = 0;
  for (size_t s = 0; s + 1 < breaks.size(); ++s)
    sum += gauss_legendre(breaks[s], breaks[s + 1], width, [&](double theta) {
      return circular_gaussian(theta, theta_l, sigma_l) *
             visible_part(b, -c - a * theta, phi_k, sigma_prime);
    });
  return sum;
}

SigmoidFit fit_sigmoid_gain(const CircularGaussianCdf& theta_cdf,
                            const CircularGaussianCdf& phi_cdf, double beta) {
  const double g_theta = std::cos(beta), g_phi = std::sin(beta);
  const double s = gaussian_spread(theta_cdf.sigma(), phi_cdf.sigma(), g_theta, g_phi);
  constexpr int kSamples = 65;
  const double d_max = std::min(4.0 * s, kPi);
  std::vector<double> ds(kSamples), hs(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    ds[i] = -d_max + 2.0 * d_max * i / (kSamples - 1);
    hs[i] = occluded_ratio_h(theta_cdf, phi_cdf, ds[i], g_theta, g_phi);
  }
  // One-parameter nonlinear least squares by Gauss–Newton from the logistic-probit match
  // κ ≈ 1.702/s, with step halving so the residual never grows.
  auto residual = [&](double kappa) {
    double r = 0;
    for (int i = 0; i < kSamples; ++i) r += std::pow(sigmoid(kappa, ds[i]) - hs[i], 2);
    return r;
  };
  double kappa = 1.702 / s;
  double r = residual(kappa);
  for (int iter = 0; iter < 50; ++iter) {
    double jtj = 0, jtr = 0;
    for (int i = 0; i < kSamples; ++i) {
      const double y = sigmoid(kappa, ds[i]);
      const double dy = ds[i] * y * (1 - y);  // ∂sigmoid/∂κ
      jtj += dy * dy;
      jtr += dy * (y - hs[i]);
    }
    if (jtj <= 0) break;
    double step = -jtr / jtj;
    double next = kappa + step, r_next = residual(next);
    while ((r_next > r || next <= 0) && std::abs(step) > 1e-12 * kappa) {
      step *= 0.5;
      next = kappa + step;
      r_next = residual(next);
    }
    if (!(r_next <= r)) break;
    const bool converged = std::abs(next - kappa) < 1e-10 * kappa;
    kappa = next;
    r = r_next;
    if (converged) break;
  }
  SigmoidFit fit;
  fit.kappa = kappa;
  fit.rms_error = std::sqrt(r / kSamples);
  // Max error over the whole d range the runtime can meet (dense near the transition).
  double worst = 0;
  for (int i = 0; i < kSamples; ++i) worst = std::max(worst, std::abs(sigmoid(kappa, ds[i]) - hs[i]));
  for (int i = 0; i <= 32; ++i) {
    const double d = -kPi + 2 * kPi * i / 32.0;
    worst = std::max(worst, std::abs(sigmoid(kappa, d) -
                                     occluded_ratio_h(theta_cdf, phi_cdf, d, g_theta, g_phi)));
  }
  fit.max_error = worst;
  return fit;
}

SigmoidGainTable fit_sigmoid_gain_table(const SigmoidGainTableSpec& spec,
                                        const std::function<void(int, int)>& progress) {
  if (spec.sigma_l_count < 2 || spec.sigma_prime_count < 2 || spec.beta_count < 2 ||
      spec.sigma_l_count * spec.sigma_prime_count * spec.beta_count > (1 << 22))
    throw std::invalid_argument("sigmoid gain table: each axis needs 2+ samples, 4M cells at most");
  if (!(spec.sigma_min > 0) || !(spec.sigma_max > spec.sigma_min) || !std::isfinite(spec.sigma_max))
    throw std::invalid_argument("sigmoid gain table: need 0 < sigma_min < sigma_max");
  const int nl = spec.sigma_l_count, np = spec.sigma_prime_count, nb = spec.beta_count;
  // A placeholder table of unit gains gives the axes' node positions.
  const SigmoidGainTable table = SigmoidGainTable::from_gains(spec, std::vector<float>(size_t(nl) * np * nb, 1.0f), 0.0);
  std::vector<float> gains(size_t(nl) * np * nb);
  std::vector<CircularGaussianCdf> cdf_l, cdf_p;
  for (int i = 0; i < nl; ++i) cdf_l.emplace_back(table.sigma_l_at(i));
  for (int j = 0; j < np; ++j) cdf_p.emplace_back(table.sigma_prime_at(j));
  double worst = 0;
  int done = 0;
#pragma omp parallel for collapse(2) schedule(dynamic) reduction(max : worst)
  for (int i = 0; i < nl; ++i)
    for (int j = 0; j < np; ++j) {
      for (int k = 0; k < nb; ++k) {
        const SigmoidFit f = fit_sigmoid_gain(cdf_l[i], cdf_p[j], table.beta_at(k));
        const double beta = table.beta_at(k);
        gains[(size_t(i) * np + j) * nb + k] =
            float(f.kappa * gaussian_spread(table.sigma_l_at(i), table.sigma_prime_at(j),
                                            std::cos(beta), std::sin(beta)));
        worst = std::max(worst, f.max_error);
      }
      if (progress) {
#pragma omp critical
        progress(++done, nl * np);
      }
    }
  return SigmoidGainTable::from_gains(spec, std::move(gains), worst);
}

Eq12Errors eq12_half_plane_errors(double sigma_l, double sigma_prime, int n) {
  if (n < 1 || n > 4096) throw std::invalid_argument("Eq. 12 error grid must be 1..4096 wide");
  const CircularGaussianCdf cdf_l(sigma_l), cdf_p(sigma_prime);
  // I and Eq. 12 are separable for V = [θ > 0]: the φ factor ∫g^c(φ; φ_k) is common to both.
  std::vector<double> z_phi(n);
  for (int b = 0; b < n; ++b)
    z_phi[b] = integrate_circular_gaussian(-kHalfPi, kHalfPi, -kHalfPi + (b + 0.5) * kPi / n,
                                           sigma_prime);
  double sum_exact = 0, sum_eq13 = 0;
  for (int a = 0; a < n; ++a) {
    const double theta_l = -kHalfPi + (a + 0.5) * kPi / n;
    const double truth_theta = integrate_circular_gaussian(0.0, kHalfPi, theta_l, sigma_l);
    const double z_theta = integrate_circular_gaussian(-kHalfPi, kHalfPi, theta_l, sigma_l);
    // H with d = θ_l (the signed distance to the line θ = 0) and ∇d = (1, 0).
    const double h = occluded_ratio_h(cdf_l, cdf_p, theta_l, 1.0, 0.0);
    for (int b = 0; b < n; ++b) {
      const double phi_k = -kHalfPi + (b + 0.5) * kPi / n;
      const double truth = truth_theta * z_phi[b];
      const double eq12 = z_theta * z_phi[b] * h;
      const double eq12_13 = circular_gaussian_pair_integral(theta_l, sigma_l, phi_k, sigma_prime) * h;
      sum_exact += std::pow(eq12 - truth, 2);
      sum_eq13 += std::pow(eq12_13 - truth, 2);
    }
  }
  const double count = double(n) * n;
  return {std::sqrt(sum_exact / count), std::sqrt(sum_eq13 / count)};
}

}  // namespace weft
