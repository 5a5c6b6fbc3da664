// The azimuthal table T_m(φ_o, φ_k, λ') against a direct adaptive quadrature of its integral.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "bake/tables/azimuthal_bake.h"

using namespace weft;
constexpr double kPi = std::numbers::pi;

// Adaptive Simpson: independent of the table's midpoint rule and grids.
static double simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
                      double whole, double eps, int depth) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * eps) return left + right + (left + right - whole) / 15;
  return simpson(f, a, m, fa, flm, fm, left, eps / 2, depth - 1) + simpson(f, m, b, fm, frm, fb, right, eps / 2, depth - 1);
}
// Split first so no lobe narrower than the interval hides between the first three samples.
static double integrate(const std::function<double(double)>& f, double a, double b) {
  constexpr int kPieces = 256;
  double sum = 0.0;
  for (int k = 0; k < kPieces; ++k) {
    const double lo = a + (b - a) * k / kPieces, hi = a + (b - a) * (k + 1) / kPieces;
    const double fa = f(lo), fb = f(hi), fm = f(0.5 * (lo + hi));
    sum += simpson(f, lo, hi, fa, fm, fb, (hi - lo) / 6 * (fa + 4 * fm + fb), 1e-12, 30);
  }
  return sum;
}
static double direct(int m, double phi_o, double phi_k, double lp) {
  return integrate([&](double x) { return std::exp(lp * (std::cos(x - phi_k) - 1.0)) * std::pow(std::cos(0.5 * (x - phi_o)), m); },
                   -kPi / 2, kPi / 2);
}

static const AzimuthalTable& table() {
  static const AzimuthalTable t = bake_azimuthal_table();
  return t;
}

TEST(AzimuthalTable, FullCircleIntegralMatchesQuadrature) {
  for (double lp : {0.0, 0.5, 3.0, 40.0, 499.0, 501.0, 2000.0}) {
    const double q = integrate([&](double x) { return std::exp(lp * (std::cos(x) - 1.0)); }, -kPi, kPi);
    EXPECT_NEAR(circular_gaussian_full_integral(lp), q, 1e-8 * q) << "λ' " << lp;
  }
}

TEST(AzimuthalTable, NodesMatchDirectIntegral) {
  const AzimuthalTable& t = table();
  std::mt19937 rng(5);
  for (int k = 0; k < 100; ++k) {
    const int m = rng() % 11, l = rng() % t.settings.lambda_nodes, ik = rng() % t.settings.phi_k_nodes,
              io = rng() % t.settings.phi_o_nodes;
    const double lp = t.lambda_node(l), po = t.phi_o_node(io), pk = t.phi_k_node(ik);
    const double d = direct(m, po, pk, lp);
    EXPECT_NEAR(t.value(m, po, pk, lp), d, 1e-5 * circular_gaussian_full_integral(lp) + 1e-6 * d)
        << "m " << m << " φ_o " << po << " φ_k " << pk << " λ' " << lp;
  }
}

// Between nodes the table is trilinear; for the moderately sharp lobes most SGs become
// (λ' ≤ 64) that is within 2 % of the lobe's full integral (measured worst: 1.1 %, where the
// lobe straddles the ±π/2 cut-off of the φ_i range).
TEST(AzimuthalTable, InterpolationIsCloseForModerateLobes) {
  const AzimuthalTable& t = table();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    const int m = rng() % 11;
    const double po = (u(rng) - 0.5) * kPi, pk = (u(rng) - 0.5) * 2 * kPi, lp = std::expm1(u(rng) * std::log1p(64.0));
    const double z = circular_gaussian_full_integral(lp);
    EXPECT_NEAR(t.value(m, po, pk, lp), direct(m, po, pk, lp), 0.02 * z) << "m " << m << " φ_o " << po << " φ_k " << pk
                                                                          << " λ' " << lp;
  }
}

TEST(AzimuthalTable, BroadLobeLimitIsThePlainCosinePowerIntegral) {
  // λ' = 0: g^c ≡ 1, and m = 0 gives the interval length π.
  EXPECT_NEAR(table().value(0, 0.3, 1.0, 0.0), kPi, 1e-4);
  EXPECT_NEAR(table().value(2, 0.0, 0.0, 0.0), direct(2, 0.0, 0.0, 0.0), 1e-4);
}
