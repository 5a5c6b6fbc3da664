// The circular-Gaussian triple product against the linear visibility: H by quadrature against brute
// force, the sigmoid of Eq. 14 within 0.01 of H, and the paper's error table for Eq. 12.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "bake/visibility/sigmoid_gain.h"
#include "core/circular_gaussian.h"

using namespace weft;

namespace {

constexpr double kPi = std::numbers::pi;

// Nested midpoint rule, independent of the code's Gauss–Legendre panels and cumulative tables:
// the outer axis is the one with the smaller line coefficient (so its integrand is continuous),
// the inner one is integrated over exactly its visible interval.
double brute_triple_product(double theta_l, double phi_k, double sl, double sp, double a,
                            double b, double c, int n) {
  auto g = [](double x, double mu, double s) { return std::exp(2 / (s * s) * (std::cos(x - mu) - 1)); };
  if (a == 0 && b == 0) a = 1e-300, c = c > 0 ? 1 : -1;
  const bool outer_theta = std::abs(a) <= std::abs(b);
  const double ao = outer_theta ? a : b, ai = outer_theta ? b : a;
  const double mo = outer_theta ? theta_l : phi_k, mi = outer_theta ? phi_k : theta_l;
  const double so = outer_theta ? sl : sp, si = outer_theta ? sp : sl;
  const double step = kPi / n;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double x = -kPi / 2 + (i + 0.5) * step;
    const double t = -(c + ao * x) / ai;  // inner visible where ai·y > ai·t
    const double lo = ai > 0 ? std::max(t, -kPi / 2) : -kPi / 2;
    const double hi = ai > 0 ? kPi / 2 : std::min(t, kPi / 2);
    if (hi <= lo) continue;
    const double w = (hi - lo) / n;
    double inner = 0;
    for (int j = 0; j < n; ++j) inner += g(lo + (j + 0.5) * w, mi, si);
    sum += g(x, mo, so) * inner * w;
  }
  return sum * step;
}

}  // namespace

TEST(TripleProduct, QuadratureMatchesBruteForce) {
  struct Case { double tl, pk, sl, sp, a, b, c; };
  for (const Case& k : {Case{0.3, -0.2, 0.5, 0.25, 0.8, 0.6, 0.1}, Case{-1.0, 0.7, 0.2, 0.7, -0.3, 1.0, 0.4},
                        Case{1.2, 1.4, 0.7, 0.15, 1.0, 0.0, -0.5}, Case{0.0, 0.0, 0.3, 0.3, 0.0, -1.0, 0.2}}) {
    const double want = brute_triple_product(k.tl, k.pk, k.sl, k.sp, k.a, k.b, k.c, 2000);
    EXPECT_NEAR(triple_product_linear_visibility(k.tl, k.pk, k.sl, k.sp, k.a, k.b, k.c), want,
                2e-4 * std::max(want, 1e-3));
  }
}

TEST(TripleProduct, HIsTheZeroMeanRatioOfEq12) {
  // H(σ_l, σ', d, ∇d) is the triple product with both means at 0, normalised.
  for (double beta : {0.0, 0.4, 1.1, kPi / 2, 2.5}) {
    const double sl = 0.3, sp = 0.45, d = 0.12, gt = std::cos(beta), gp = std::sin(beta);
    const double want = brute_triple_product(0, 0, sl, sp, gt, gp, d, 2000) /
                        brute_triple_product(0, 0, sl, sp, 0, 0, 1, 2000);
    EXPECT_NEAR(occluded_ratio_h(sl, sp, d, gt, gp), want, 2e-4);
  }
}

TEST(TripleProduct, HTendsToTheGaussianCdfForNarrowLobes) {
  // Untruncated and nearly Gaussian: H = Φ(d / s) with s = gaussian_spread.
  const double sl = 0.05, sp = 0.08;
  for (double beta : {0.0, 0.7, 1.3})
    for (double d : {-0.08, -0.02, 0.0, 0.03, 0.1}) {
      const double s = gaussian_spread(sl, sp, std::cos(beta), std::sin(beta));
      const double phi = 0.5 * std::erfc(-d / (s * std::sqrt(2.0)));
      EXPECT_NEAR(occluded_ratio_h(sl, sp, d, std::cos(beta), std::sin(beta)), phi, 2e-3);
    }
}

TEST(TripleProduct, ExactHTendsToCoresUntruncatedClosedForm) {
  // core's linear_visibility_ratio is H for Gaussians over the whole plane; for narrow lobes the
  // square and the circular shape stop mattering and the exact H must agree with it.
  for (double beta : {0.2, 0.9, 1.4})
    for (double d : {-0.05, 0.0, 0.04})
      EXPECT_NEAR(occluded_ratio_h(0.04, 0.07, d, std::cos(beta), std::sin(beta)),
                  linear_visibility_ratio(0.04, 0.07, d, std::cos(beta), std::sin(beta)), 1e-3);
}

TEST(SigmoidGain, FitWithinOneHundredthOfHAtThePapersFigure5Bandwidths) {
  // Fig. 5: (σ_l, σ'_l) = (1/(4√2), 1/√2) and (1/16, 1/(2√2)); paper: max errors 0.0093, 0.0094.
  const double r2 = std::sqrt(2.0);
  for (auto [sl, sp] : {std::pair{1 / (4 * r2), 1 / r2}, std::pair{1.0 / 16, 1 / (2 * r2)}}) {
    const CircularGaussianCdf cl(sl), cp(sp);
    for (int k = 0; k <= 8; ++k) {
      const double beta = k * kPi / 16;
      const SigmoidFit fit = fit_sigmoid_gain(cl, cp, beta);
      // Independent check of the fit on a fresh dense d grid, H by quadrature.
      double worst = 0;
      for (int i = 0; i <= 400; ++i) {
        const double d = -1.5 + 3.0 * i / 400;
        worst = std::max(worst, std::abs(sigmoid(fit.kappa, d) -
                                          occluded_ratio_h(cl, cp, d, std::cos(beta), std::sin(beta))));
      }
      EXPECT_LE(worst, 0.01) << "σ_l " << sl << " σ' " << sp << " β " << beta;
      EXPECT_NEAR(worst, fit.max_error, 5e-4);
      // The logistic–probit relation: κ·s near 1.70 when truncation is mild.
      EXPECT_NEAR(fit.kappa * gaussian_spread(sl, sp, std::cos(beta), std::sin(beta)), 1.70, 0.08);
    }
  }
}

TEST(SigmoidGain, InterpolatedTableStaysWithinOneHundredthOffItsNodes) {
  SigmoidGainTableSpec spec;
  spec.sigma_l_count = 6;
  spec.sigma_prime_count = 6;
  spec.beta_count = 33;
  const SigmoidGainTable table = fit_sigmoid_gain_table(spec);
  EXPECT_LE(table.max_fit_error(), 0.01);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (int t = 0; t < 60; ++t) {
    const double sl = spec.sigma_min * std::pow(spec.sigma_max / spec.sigma_min, u(rng));
    const double sp = spec.sigma_min * std::pow(spec.sigma_max / spec.sigma_min, u(rng));
    const double beta = u(rng) * 2 * kPi, len = 0.5 + u(rng);  // |∇d| ≠ 1 folds into d
    const double gt = len * std::cos(beta), gp = len * std::sin(beta);
    const CircularGaussianCdf cl(sl), cp(sp);
    const double s = gaussian_spread(sl, sp, gt, gp) * len;
    for (int i = 0; i <= 20; ++i) {
      const double d = (-3 + 6.0 * i / 20) * s;
      worst = std::max(worst, std::abs(table.h(sl, sp, d, gt, gp) - occluded_ratio_h(cl, cp, d, gt, gp)));
    }
  }
  EXPECT_LE(worst, 0.01);
  EXPECT_GT(worst, 0.005);  // a sigmoid is not a Gaussian CDF: the error is real, not zero
}

TEST(SigmoidGain, RejectsBadArguments) {
  EXPECT_THROW(CircularGaussianCdf(0.0), std::invalid_argument);
  EXPECT_THROW(occluded_ratio_h(0.3, 0.3, std::nan(""), 1, 0), std::invalid_argument);
  SigmoidGainTableSpec bad;
  bad.beta_count = 1;
  EXPECT_THROW(fit_sigmoid_gain_table(bad), std::invalid_argument);
}

// Seed 000 §4: RMSE between I and Eq. 12 for V = [θ > 0], means uniform in [−π/2, π/2]².
// We compute I and both factors by converged quadrature and the means on a 64×64 grid.
//  - (1/2, 1/2) and (1/2, 1/8): ours 1.5496e−4 and 4.0756e−5 against 1.5514e−4 and
//    4.0907e−5, within 0.4%: this is the error of moving the means to 0 in Eq. 12, the
//    quantity the paper measured.
//  - (1/2, 1/32): ours 1.034e−5. With V = [θ > 0] the φ factor is common to I and Eq. 12,
//    so the RMSE must scale with ∫g^c(φ; φ_k, σ') ≈ √π σ': 1.55e−4 → 4.08e−5 → 1.03e−5
//    for σ' = 1/2, 1/8, 1/32. The paper's 0.0049 breaks that scaling by 500×; it is most
//    likely the quadrature of a σ = 1/32 lobe on a grid too coarse for it.
//  - (1/8, 1/2) and (1/32, 1/2): exactly 0 up to rounding (ours ~1e−16): a lobe with
//    σ_l ≤ 1/8 has no mass beyond ±π/2 of its mean, so moving the mean changes nothing.
//    The paper's 1.7207e−8 is its quadrature floor; its 0.0035 at σ_l = 1/32 is again
//    the under-resolved sharp lobe.
//  - With Eq. 13 for the first factor (Gaussians for circular Gaussians, as at run time)
//    the RMSEs are 1.2e−2, 1.7e−3, 4.0e−4, 1.9e−3, 4.5e−4: the paper's table does not
//    include that approximation (its (1/2, 1/2) entry is 80× smaller).
TEST(Eq12ErrorTable, ReproducesThePapersHalfPlaneAnalysis) {
  struct Row { double sl, sp, paper; };
  const Row rows[] = {{0.5, 0.5, 1.5514e-4}, {0.5, 0.125, 4.0907e-5}, {0.5, 1.0 / 32, 0.0049},
                      {0.125, 0.5, 1.7207e-8}, {1.0 / 32, 0.5, 0.0035}};
  for (const Row& r : rows) {
    const Eq12Errors e = eq12_half_plane_errors(r.sl, r.sp, 64);
    std::printf("  (σ_l, σ'_k) = (%.5f, %.5f): RMSE Eq.12 %.4e  with Eq.13 %.4e  paper %.4e\n",
                r.sl, r.sp, e.rmse_eq12_exact, e.rmse_eq12_eq13, r.paper);
    if (r.sl == 0.5 && r.sp >= 0.125) {
      EXPECT_NEAR(e.rmse_eq12_exact / r.paper, 1.0, 0.01);  // agree within 1%
    } else if (r.sl == 0.5) {
      // Expected from the σ' scaling of the rows above, not the paper's outlier.
      EXPECT_NEAR(e.rmse_eq12_exact, 4.0907e-5 / 4, 0.1 * 4.0907e-5 / 4);
      EXPECT_LT(e.rmse_eq12_exact, r.paper / 100);
    } else {
      EXPECT_LT(e.rmse_eq12_exact, 1e-12);  // at or below the paper's floor
    }
    EXPECT_GT(e.rmse_eq12_eq13, e.rmse_eq12_exact);  // Eq. 13 adds its own error
  }
}
