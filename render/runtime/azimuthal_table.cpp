#include "runtime/azimuthal_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;

// Position of x on a node axis [lo, hi] with n nodes: cell index and fraction.
void locate(double x, double lo, double hi, int n, int& i, double& f) {
  const double s = std::clamp((x - lo) / (hi - lo), 0.0, 1.0) * (n - 1);
  i = std::clamp(static_cast<int>(std::floor(s)), 0, n - 2);
  f = s - i;
}
}  // namespace

double circular_gaussian_full_integral(double lp) {
  if (!(lp >= 0.0)) throw std::invalid_argument("circular_gaussian_full_integral: λ' must be >= 0");
  if (lp < 500.0) return 2.0 * kPi * std::exp(-lp) * std::cyl_bessel_i(0.0, lp);
  // e^{−x} I_0(x) ~ (1 + 1/(8x) + 9/(128x²) + 225/(3072x³)) / √(2πx): relative error < 1e-12 here.
  const double x = lp;
  return 2.0 * kPi * (1.0 + 1.0 / (8 * x) + 9.0 / (128 * x * x) + 225.0 / (3072 * x * x * x)) / std::sqrt(2 * kPi * x);
}

double AzimuthalTable::phi_o_node(int i) const { return -kPi / 2 + kPi * i / (settings.phi_o_nodes - 1); }
double AzimuthalTable::phi_k_node(int i) const { return -kPi + 2 * kPi * i / (settings.phi_k_nodes - 1); }
double AzimuthalTable::lambda_node(int i) const {
  const double u = double(i) / (settings.lambda_nodes - 1);
  return std::expm1(u * std::log1p(settings.lambda_max));
}

double AzimuthalTable::node_ratio(int m, int l, int k, int o) const {
  const auto& s = settings;
  return ratio[((size_t(m) * s.lambda_nodes + l) * s.phi_k_nodes + k) * s.phi_o_nodes + o];
}

double AzimuthalTable::value(int m, double phi_o, double phi_k, double lp) const {
  const auto& s = settings;
  if (m < 0 || m > s.max_power) throw std::out_of_range("AzimuthalTable::value: power out of range");
  if (!(std::isfinite(phi_o) && std::isfinite(phi_k) && lp >= 0.0)) return 0.0;
  phi_k = std::remainder(phi_k, 2 * kPi);
  // Past λ_max the ratio T/Z has settled (the lobe is narrower than anything else in φ), but Z
  // keeps shrinking as 1/√λ': take the ratio at the last node and Z at the true λ'.
  const double z = circular_gaussian_full_integral(lp);
  lp = std::min(lp, s.lambda_max);
  int io, ik, il;
  double fo, fk, fl;
  locate(phi_o, -kPi / 2, kPi / 2, s.phi_o_nodes, io, fo);
  locate(phi_k, -kPi, kPi, s.phi_k_nodes, ik, fk);
  locate(std::log1p(lp) / std::log1p(s.lambda_max), 0.0, 1.0, s.lambda_nodes, il, fl);
  double r = 0.0;
  for (int dl = 0; dl < 2; ++dl)
    for (int dk = 0; dk < 2; ++dk)
      for (int d0 = 0; d0 < 2; ++d0)
        r += (dl ? fl : 1 - fl) * (dk ? fk : 1 - fk) * (d0 ? fo : 1 - fo) * node_ratio(m, il + dl, ik + dk, io + d0);
  return r * z;
}

}  // namespace weft
