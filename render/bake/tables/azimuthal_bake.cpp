#include "bake/tables/azimuthal_bake.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

AzimuthalTable bake_azimuthal_table(const AzimuthalTableSettings& s) {
  if (s.phi_o_nodes < 2 || s.phi_k_nodes < 2 || s.lambda_nodes < 2 || s.max_power < 0 || s.max_power > 32 ||
      !(s.lambda_max > 0.0) || s.quadrature_points < 16)
    throw std::invalid_argument("bake_azimuthal_table: unusable settings");
  AzimuthalTable t;
  t.settings = s;
  const int q = s.quadrature_points, K = s.phi_k_nodes, O = s.phi_o_nodes, M = s.max_power + 1;
  t.ratio.resize(size_t(M) * s.lambda_nodes * K * O);
  // Midpoint rule over φ_i ∈ [−π/2, π/2]: the integrand is smooth inside the interval.
  const double h = kPi / q;
  Eigen::VectorXd phi_i(q);
  for (int i = 0; i < q; ++i) phi_i[i] = -kPi / 2 + (i + 0.5) * h;
  // C_m[φ_i, φ_o] = cos^m((φ_i − φ_o)/2), for every m.
  std::vector<Eigen::MatrixXd> c(M, Eigen::MatrixXd(q, O));
  for (int o = 0; o < O; ++o)
    for (int i = 0; i < q; ++i) {
      const double base = std::cos(0.5 * (phi_i[i] - t.phi_o_node(o)));
      double p = 1.0;
      for (int m = 0; m < M; ++m, p *= base) c[m](i, o) = p;
    }
  // Levels are independent; one per thread of execution keeps each small GEMM single-threaded
  // (splitting 65×2048×33 products across threads costs more than it saves).
#pragma omp parallel for schedule(dynamic, 1)
  for (int l = 0; l < s.lambda_nodes; ++l) {
    const double lp = t.lambda_node(l);
    const double inv_z = 1.0 / circular_gaussian_full_integral(lp);
    Eigen::MatrixXd g(K, q);  // g^c(φ_i; φ_k)·h / Z
    for (int k = 0; k < K; ++k)
      for (int i = 0; i < q; ++i) g(k, i) = std::exp(lp * (std::cos(phi_i[i] - t.phi_k_node(k)) - 1.0)) * h * inv_z;
    for (int m = 0; m < M; ++m) {
      const Eigen::MatrixXd r = g * c[m];  // K × O
      for (int k = 0; k < K; ++k)
        for (int o = 0; o < O; ++o)
          t.ratio[((size_t(m) * s.lambda_nodes + l) * K + k) * O + o] = static_cast<float>(r(k, o));
    }
  }
  return t;
}

double azimuthal_interpolation_error(const AzimuthalTable& t, int stride) {
  const auto& s = t.settings;
  const int q = s.quadrature_points;
  const double h = kPi / q;
  double worst = 0.0;
  for (int l = 0; l + 1 < s.lambda_nodes; l += stride)
    for (int k = 0; k + 1 < s.phi_k_nodes; k += stride)
      for (int o = 0; o + 1 < s.phi_o_nodes; o += stride) {
        const double lp = std::expm1(0.5 * (std::log1p(t.lambda_node(l)) + std::log1p(t.lambda_node(l + 1))));
        const double pk = 0.5 * (t.phi_k_node(k) + t.phi_k_node(k + 1));
        const double po = 0.5 * (t.phi_o_node(o) + t.phi_o_node(o + 1));
        const double z = circular_gaussian_full_integral(lp);
        for (int m : {1, 6, 10}) {
          if (m > s.max_power) continue;
          double sum = 0.0;
          for (int i = 0; i < q; ++i) {
            const double x = -kPi / 2 + (i + 0.5) * h;
            sum += std::exp(lp * (std::cos(x - pk) - 1.0)) * std::pow(std::cos(0.5 * (x - po)), m);
          }
          worst = std::max(worst, std::abs(t.value(m, po, pk, lp) - sum * h) / z);
        }
      }
  return worst;
}

}  // namespace weft
