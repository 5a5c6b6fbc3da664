#include "runtime/sigmoid_gain_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace weft {

namespace {
constexpr double kHalfPi = std::numbers::pi / 2;
}  // namespace

double gaussian_spread(double sigma_l, double sigma_prime, double grad_theta, double grad_phi) {
  const double len2 = grad_theta * grad_theta + grad_phi * grad_phi;
  return std::sqrt(0.5 * (sigma_l * sigma_l * grad_theta * grad_theta +
                          sigma_prime * sigma_prime * grad_phi * grad_phi) / len2);
}

double SigmoidGainTable::sigma_l_at(int i) const {
  const int n = spec_.sigma_l_count;
  return spec_.sigma_min * std::pow(spec_.sigma_max / spec_.sigma_min, n > 1 ? double(i) / (n - 1) : 0.0);
}
double SigmoidGainTable::sigma_prime_at(int j) const {
  const int n = spec_.sigma_prime_count;
  return spec_.sigma_min * std::pow(spec_.sigma_max / spec_.sigma_min, n > 1 ? double(j) / (n - 1) : 0.0);
}
double SigmoidGainTable::beta_at(int k) const {
  const int n = spec_.beta_count;
  return n > 1 ? kHalfPi * k / (n - 1) : 0.0;
}

SigmoidGainTable SigmoidGainTable::from_gains(const SigmoidGainTableSpec& spec, std::vector<float> gains,
                                              double max_fit_error) {
  if (spec.sigma_l_count < 2 || spec.sigma_prime_count < 2 || spec.beta_count < 2 ||
      !(spec.sigma_min > 0 && spec.sigma_max > spec.sigma_min))
    throw std::invalid_argument("sigmoid gain table: bad spec");
  if (gains.size() != size_t(spec.sigma_l_count) * spec.sigma_prime_count * spec.beta_count)
    throw std::invalid_argument("sigmoid gain table: " + std::to_string(gains.size()) + " gains for a " +
                                std::to_string(spec.sigma_l_count) + "x" + std::to_string(spec.sigma_prime_count) +
                                "x" + std::to_string(spec.beta_count) + " table");
  for (float g : gains)
    if (!(std::isfinite(g) && g > 0)) throw std::invalid_argument("sigmoid gain table: non-finite or non-positive gain");
  SigmoidGainTable t;
  t.spec_ = spec;
  t.kappa_ = std::move(gains);
  t.max_fit_error_ = max_fit_error;
  return t;
}

double SigmoidGainTable::kappa(double sigma_l, double sigma_prime, double grad_theta,
                               double grad_phi) const {
  const double log_range = std::log(spec_.sigma_max / spec_.sigma_min);
  auto axis = [&](double sigma, int n) {
    const double u = std::log(std::clamp(sigma, spec_.sigma_min, spec_.sigma_max) / spec_.sigma_min) /
                     log_range * (n - 1);
    return std::clamp(u, 0.0, double(n - 1));
  };
  const double beta = std::atan2(std::abs(grad_phi), std::abs(grad_theta));
  const double u[3] = {axis(sigma_l, spec_.sigma_l_count), axis(sigma_prime, spec_.sigma_prime_count),
                       std::clamp(beta / kHalfPi * (spec_.beta_count - 1), 0.0, double(spec_.beta_count - 1))};
  const int n[3] = {spec_.sigma_l_count, spec_.sigma_prime_count, spec_.beta_count};
  int i0[3];
  double t[3];
  for (int a = 0; a < 3; ++a) {
    i0[a] = std::min(int(u[a]), n[a] - 2);
    t[a] = u[a] - i0[a];
  }
  double normalized = 0;
  for (int c = 0; c < 8; ++c) {
    double w = 1;
    int idx[3];
    for (int a = 0; a < 3; ++a) {
      const int bit = (c >> a) & 1;
      idx[a] = i0[a] + bit;
      w *= bit ? t[a] : 1 - t[a];
    }
    if (w == 0) continue;
    normalized += w * double(kappa_[(size_t(idx[0]) * n[1] + idx[1]) * n[2] + idx[2]]);
  }
  return normalized / gaussian_spread(sigma_l, sigma_prime, grad_theta, grad_phi);
}

double SigmoidGainTable::h(double sigma_l, double sigma_prime, double d, double grad_theta,
                           double grad_phi) const {
  const double len = std::hypot(grad_theta, grad_phi);
  if (len == 0) return d > 0 ? 1.0 : (d < 0 ? 0.0 : 0.5);
  return sigmoid(kappa(sigma_l, sigma_prime, grad_theta, grad_phi), d / len);
}

}  // namespace weft
