// Weighting tables against an independent quadrature of ∫G·W / ∫G, the SVD
// compression against its own reported error, and the rank choice against the error target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <map>
#include <random>

#include "runtime/hemisphere_grid.h"
#include "bake/tables/low_rank.h"
#include "bake/tables/sg_convolution.h"
#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "core/fabric.h"

using namespace weft;
constexpr double kPi = std::numbers::pi;

static Fabric preset(const std::string& name) { return load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics"); }

// Eq. 10 by an SG-warped grid around ξ, independent of the baker's grids: in ξ's frame,
// x = (e^{λ(cos β − 1)} − e^{−2λ}) / (1 − e^{−2λ}) is uniform under G dω, so a midpoint grid
// in (x, azimuth) samples G exactly; W and the hemisphere indicator are what remain.
static double direct_T(const ClothBsdf& bsdf, int t, double lambda, glm::dvec3 xi, glm::dvec3 wo, int n = 200) {
  ClothBsdf::Point p = bsdf.at(SurfaceFrame{});
  std::vector<double> w(bsdf.total_samples());
  const glm::dvec3 a = std::abs(xi.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(a, xi)), e2 = glm::cross(xi, e1);
  const double floor = std::exp(-2.0 * lambda);
  double num = 0.0, den = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) / n;
    const double c = std::clamp(1.0 + std::log(x * (1.0 - floor) + floor) / lambda, -1.0, 1.0);
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    for (int k = 0; k < 2 * n; ++k) {
      const double phi = (k + 0.5) * kPi / n;
      const glm::dvec3 wi = c * xi + s * (std::cos(phi) * e1 + std::sin(phi) * e2);
      if (wi.z <= 0.0) continue;
      p.weights(wi, wo, w);
      num += w[t];
      den += 1.0;
    }
  }
  return den > 0 ? num / den : 0.0;
}

// square → unit direction above the horizon → the same square point, at 2000 random points.
static void expect_round_trip(glm::dvec3 (*to_hemisphere)(glm::dvec2), glm::dvec2 (*to_square)(glm::dvec3),
                              unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const glm::dvec2 s(u(rng), u(rng));
    const glm::dvec3 w = to_hemisphere(s);
    EXPECT_NEAR(glm::length(w), 1.0, 1e-12);
    EXPECT_GE(w.z, -1e-15);
    const glm::dvec2 back = to_square(w);
    EXPECT_NEAR(back.x, s.x, 1e-9);
    EXPECT_NEAR(back.y, s.y, 1e-9);
  }
}

TEST(HemisphereGrid, SquareRoundTripAndEqualArea) {
  expect_round_trip(hemisphere_from_square, square_from_hemisphere, 3);
  // Equal area: the fraction of cells above z = c is the cap's share 1 − c of the hemisphere.
  const HemisphereCellGrid g{200};
  int above = 0;
  for (int i = 0; i < g.size(); ++i) above += g.centre(i).z > 0.5;
  EXPECT_NEAR(double(above) / g.size(), 0.5, 0.01);
}

// The node grid's square: a round trip, each ring at disk radius r(ρ) = ρ(b − (b − 1)ρ), i.e.
// z = 1 − r² (checked on both axes and a diagonal), the horizon on the border, and the last ring
// step a times the equal-angle step (the equal-area square's is 1.25×; hemisphere_grid.h says why).
TEST(HemisphereGrid, NodeRingsAreDensestAtTheHorizon) {
  expect_round_trip(hemisphere_from_node_square, node_square_from_hemisphere, 5);
  const double a = kNodeRingHorizonSpacing, pi = kPi;
  for (double rho : {0.05, 0.3, 0.7, 0.95, 1.0})
    for (glm::dvec2 dir : {glm::dvec2(1, 0), glm::dvec2(0, -1), glm::dvec2(1, 1)}) {
      const double b = 2 - a * pi / 4, r = rho * (b - (b - 1) * rho);
      EXPECT_NEAR(hemisphere_from_node_square(rho * dir).z, 1 - r * r, 1e-12) << rho;
    }
  EXPECT_NEAR(hemisphere_from_node_square({1.0, 0.3}).z, 0.0, 1e-12);
  EXPECT_NEAR(hemisphere_from_node_square({0.0, 0.0}).z, 1.0, 1e-15);
  const HemisphereNodeGrid g{48};
  const double h = 2.0 / (g.n - 1);
  const double last = std::acos(g.node(g.n * (g.n / 2) + g.n - 2).z);  // one node in from the horizon at +x
  EXPECT_NEAR((0.5 * pi - last) / (0.5 * pi * h), a, 0.06);  // 0.245 over the finite step
  const double equal_area_last = std::acos(hemisphere_from_square({1.0 - h, 0.0}).z);
  EXPECT_GT((0.5 * pi - equal_area_last) / (0.5 * pi * h), 1.2);
  // Taps reproduce a node exactly.
  const BilinearTap t = g.tap(g.node(17 * g.n + 40));
  double at_node = 0;
  for (int q = 0; q < 4; ++q) at_node += (t.index[q] == 17 * g.n + 40) * t.weight[q];
  EXPECT_NEAR(at_node, 1.0, 1e-9);
}

TEST(HemisphereGrid, BelowHorizonMapsToNearestHorizonPoint) {
  const glm::dvec2 s = square_from_hemisphere(glm::normalize(glm::dvec3(1, 1, -0.5)));
  const glm::dvec3 w = hemisphere_from_square(s);
  EXPECT_NEAR(w.z, 0.0, 1e-12);
  EXPECT_NEAR(w.x, std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(w.y, std::sqrt(0.5), 1e-9);
}

// The G·W product at grid nodes against the warped quadrature.
TEST(WeightingBake, ConvolutionMatchesDirectQuadrature) {
  const Fabric fabric = preset("linen_plain");
  BakeSettings s;
  const ClothBsdf bsdf(fabric, s.tangent_samples);
  const HemisphereNodeGrid nodes{48};
  std::vector<glm::dvec3> wo = {nodes.node(20 * 48 + 30), nodes.node(40 * 48 + 9)};
  std::vector<glm::dvec3> xi = {nodes.node(24 * 48 + 24), nodes.node(10 * 48 + 37), nodes.node(47 * 48 + 20),
                                nodes.node(30 * 48 + 6)};
  const WeightGrid grid = evaluate_weight_grid(bsdf, s.wi_resolution, wo);
  for (double lambda : {4.0, 64.0, 1024.0}) {
    const SgKernel k = sg_kernel(grid.wi, xi, lambda, quadrature_resolution_for(s, lambda));
    for (int t : {0, 4}) {
      const std::vector<float> tv = convolve_weights(grid, t, k);
      for (size_t o = 0; o < wo.size(); ++o)
        for (size_t x = 0; x < xi.size(); ++x) {
          const double direct = direct_T(bsdf, t, lambda, xi[x], wo[o]);
          const double baked = tv[o * xi.size() + x];
          // Worst case is ξ on the horizon with λ = 1024: the lobe is cut in half by the horizon
          // and sees only the band of W within ~2° of it, which the 48² W nodes (4.8° apart
          // in polar angle there) interpolate linearly. Measured: 3.7e-3 there (T ≈ 0.005,
          // multiplied at runtime by ∫G·f·cos θ_i ≈ 0), ≤ 1e-3 elsewhere.
          const double tolerance = (xi[x].z < 1e-9 && lambda > 500.0) ? 5e-3 : 2e-3 + 0.01 * direct;
          EXPECT_NEAR(baked, direct, tolerance) << "λ " << lambda << " t " << t << " ξ #" << x << " ω_o #" << o;
        }
    }
  }
}

// A matrix with a known spectrum s_i = 0.7^i: the chosen rank must be the smallest whose tail
// meets the target, and the reported error must be the true ‖A − U·Vᵀ‖_F / ‖A‖_F.
static std::vector<float> known_spectrum(int rows, int cols, int rank, std::vector<double>& s) {
  std::mt19937 rng(7);
  std::normal_distribution<double> nd;
  auto orthonormal = [&](int n) {
    std::vector<std::vector<double>> q;
    while (int(q.size()) < rank) {
      std::vector<double> v(n);
      for (double& x : v) x = nd(rng);
      for (const auto& e : q) {
        double d = 0;
        for (int i = 0; i < n; ++i) d += v[i] * e[i];
        for (int i = 0; i < n; ++i) v[i] -= d * e[i];
      }
      double len = 0;
      for (double x : v) len += x * x;
      for (double& x : v) x /= std::sqrt(len);
      q.push_back(v);
    }
    return q;
  };
  const auto u = orthonormal(rows), v = orthonormal(cols);
  s.resize(rank);
  for (int k = 0; k < rank; ++k) s[k] = std::pow(0.7, k);
  std::vector<float> a(size_t(rows) * cols, 0.0f);
  for (int c = 0; c < cols; ++c)
    for (int r = 0; r < rows; ++r) {
      double x = 0;
      for (int k = 0; k < rank; ++k) x += s[k] * u[k][r] * v[k][c];
      a[size_t(c) * rows + r] = float(x);
    }
  return a;
}

static double reconstruction_error(const std::vector<float>& a, const LowRankFactors& f) {
  double err = 0, norm = 0;
  for (int c = 0; c < f.cols; ++c)
    for (int r = 0; r < f.rows; ++r) {
      double x = 0;
      for (int k = 0; k < f.rank; ++k) x += double(f.u[size_t(r) * f.rank + k]) * f.v[size_t(c) * f.rank + k];
      const double ref = a[size_t(c) * f.rows + r];
      err += (x - ref) * (x - ref);
      norm += ref * ref;
    }
  return std::sqrt(err / norm);
}

TEST(LowRank, ReportedErrorIsTheTrueErrorAndRankIsMinimal) {
  std::vector<double> s;
  const std::vector<float> a = known_spectrum(300, 200, 60, s);
  double total = 0;
  for (double x : s) total += x * x;
  int previous = 0;
  for (double target : {0.3, 0.1, 0.03, 0.01, 0.003}) {
    LowRankOptions o;
    o.relative_error = target;
    const LowRankFactors f = truncated_svd(a.data(), 300, 200, o);
    int expected = 0;
    double tail = total;
    while (std::sqrt(tail / total) > target) tail -= s[expected] * s[expected], ++expected;
    EXPECT_EQ(f.rank, expected) << "target " << target;
    EXPECT_LE(f.error, target);
    EXPECT_NEAR(f.error, reconstruction_error(a, f), 1e-4) << "target " << target;
    EXPECT_GE(f.rank, previous);
    previous = f.rank;
  }
}

TEST(LowRank, ZeroMatrixIsRankZero) {
  const std::vector<float> a(50 * 40, 0.0f);
  const LowRankFactors f = truncated_svd(a.data(), 50, 40, {});
  EXPECT_EQ(f.rank, 0);
  EXPECT_EQ(f.error, 0.0);
}

// A small real bake: the stored factors reproduce the uncompressed tables to the reported
// error; lookups at nodes equal the stored values; ranks grow as the target tightens; and the
// interpolated lookup between nodes and levels agrees with the direct quadrature.
class SmallBake : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    fabric_ = new Fabric(preset("linen_plain"));
    settings_.tangent_samples = {2, 2};
    settings_.xi_resolution = 32;
    settings_.wo_resolution = 32;
    settings_.wi_resolution = 24;
    settings_.lambda_min = 4;
    settings_.lambda_max = 16;
    settings_.lambda_levels = 3;
    settings_.svd_error = 0.01;
    tables_ = new WeightingTables(bake_weighting_tables(*fabric_, settings_));
  }
  static void TearDownTestSuite() {
    delete tables_;
    delete fabric_;
  }
  static inline Fabric* fabric_ = nullptr;
  static inline BakeSettings settings_;
  static inline WeightingTables* tables_ = nullptr;
};

TEST_F(SmallBake, FactorsReproduceTablesToTheReportedError) {
  const WeightingTables& tb = *tables_;
  ASSERT_EQ(tb.sample_count(), 4);
  ASSERT_EQ(tb.level_count(), 3);
  const ClothBsdf bsdf(*fabric_, settings_.tangent_samples);
  std::vector<glm::dvec3> xi(tb.xi_grid.size()), wo(tb.wo_grid.size());
  for (int i = 0; i < tb.xi_grid.size(); ++i) xi[i] = tb.xi_grid.node(i);
  for (int i = 0; i < tb.wo_grid.size(); ++i) wo[i] = tb.wo_grid.node(i);
  const WeightGrid grid = evaluate_weight_grid(bsdf, settings_.wi_resolution, wo);
  for (int l : {0, 2}) {
    const SgKernel k = sg_kernel(grid.wi, xi, tb.lambdas[l]);
    for (int t : {0, 3}) {
      const std::vector<float> full = convolve_weights(grid, t, k);
      double err = 0, norm = 0;
      for (int o = 0; o < grid.wo_count; ++o)
        for (int x = 0; x < k.rows; ++x) {
          const double ref = full[size_t(o) * k.rows + x];
          const double got = tb.node_value(t, l, x, o);
          err += (got - ref) * (got - ref);
          norm += ref * ref;
        }
      const CompressedTable& c = tb.table(t, l);
      EXPECT_GT(c.rank, 0);
      EXPECT_LE(c.error, settings_.svd_error);
      EXPECT_NEAR(std::sqrt(err / norm), c.error, 2e-4) << "t " << t << " level " << l;
      EXPECT_NEAR(std::sqrt(norm), c.norm, 1e-3 * c.norm);
    }
  }
}

TEST_F(SmallBake, LookupAtNodesEqualsStoredValues) {
  const WeightingTables& tb = *tables_;
  for (int x : {0, 100, 700, 1023})
    for (int o : {7, 500, 1020})
      EXPECT_NEAR(tb.value(1, tb.lambdas[1], tb.xi_grid.node(x), tb.wo_grid.node(o)), tb.node_value(1, 1, x, o), 1e-5);
}

TEST_F(SmallBake, InterpolatedLookupMatchesDirectQuadrature) {
  const WeightingTables& tb = *tables_;
  const ClothBsdf bsdf(*fabric_, settings_.tangent_samples);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 6; ++k) {
    const glm::dvec3 xi = hemisphere_from_square({u(rng), u(rng)});
    const glm::dvec3 wo = hemisphere_from_square({0.9 * u(rng), 0.9 * u(rng)});
    const double lambda = 4.0 * std::pow(4.0, 0.5 + 0.4 * u(rng));  // between levels
    const int t = k % 4;
    const double direct = direct_T(bsdf, t, lambda, xi, wo, 120);
    EXPECT_NEAR(tb.value(t, lambda, xi, wo), direct, 0.01 + 0.03 * direct) << "λ " << lambda << " t " << t;
  }
}

// T where the pillow's top needs it: seen 72–87° from the normal, under sharp lights low in the
// sky. W is steepest in ω_o there, so T's bilinear lookup is only as good as the node spacing
// near the horizon (hemisphere_grid.h); RMS over 48 lookups against the direct quadrature, at
// grid 32.
TEST(WeightingBake, GrazingViewLookupMatchesDirectQuadrature) {
  const Fabric linen = preset("linen_plain");
  BakeSettings s;
  s.tangent_samples = {3, 3};
  s.xi_resolution = s.wo_resolution = s.wi_resolution = 32;
  s.lambda_min = 256;
  s.lambda_max = 1024;
  s.lambda_levels = 2;
  const WeightingTables tb = bake_weighting_tables(linen, s);
  const ClothBsdf bsdf(linen, s.tangent_samples);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto at = [](double azimuth, double elevation) {
    return glm::dvec3(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  };
  double err = 0, norm = 0;
  for (int k = 0; k < 48; ++k) {
    const glm::dvec3 xi = at(2 * kPi * u(rng), glm::radians(2.0 + 23.0 * u(rng)));
    const glm::dvec3 wo = at(2 * kPi * u(rng), std::asin(0.05 + 0.25 * u(rng)));
    const int t = k % 6;
    const double direct = direct_T(bsdf, t, 512.0, xi, wo, 120);
    const double got = tb.value(t, 512.0, xi, wo);
    err += (got - direct) * (got - direct);
    norm += direct * direct;
  }
  const double rms = std::sqrt(err / norm);
  std::printf("grazing-view T lookups: relative RMS %.4f\n", rms);
  EXPECT_LT(rms, 0.03);  // 0.017 measured; the equal-area node square gives 0.044
}

TEST(LowRank, RankGrowsAsTheTargetTightensOnARealTable) {
  const ClothBsdf bsdf(preset("linen_plain"), 2);
  const HemisphereNodeGrid g{24};
  std::vector<glm::dvec3> xi(g.size());
  for (int i = 0; i < g.size(); ++i) xi[i] = g.node(i);
  const WeightGrid grid = evaluate_weight_grid(bsdf, 32, xi);
  const std::vector<float> table = convolve_weights(grid, 1, sg_kernel(grid.wi, xi, 16.0));
  int previous = 0;
  double previous_error = 1.0;
  for (double target : {0.1, 0.03, 0.01, 0.003, 0.001}) {
    LowRankOptions o;
    o.relative_error = target;
    const LowRankFactors f = truncated_svd(table.data(), g.size(), g.size(), o);
    EXPECT_GE(f.rank, previous) << "target " << target;
    EXPECT_LE(f.error, target);
    EXPECT_LE(f.error, previous_error);
    previous = f.rank;
    previous_error = f.error;
  }
  EXPECT_GT(previous, 1);
}

// A straight thread's samples all have tilt 0, so their W (hence T) are identical and one
// stored table serves them all; samples of different threads never share.
TEST(WeightingBake, SamplesWithTheSameTiltShareOneTable) {
  const Fabric satin = preset("polyester_satin_charmeuse");  // thread 2: offsets 0, 0
  const ClothBsdf bsdf(satin, std::array<int, 2>{2, 3});
  const HemisphereNodeGrid g{12};
  std::vector<glm::dvec3> wo(g.size());
  for (int i = 0; i < g.size(); ++i) wo[i] = g.node(i);
  const WeightGrid grid = evaluate_weight_grid(bsdf, 12, wo);
  EXPECT_EQ(grid.w[2], grid.w[4]);
  EXPECT_NE(grid.w[0], grid.w[1]);

  BakeSettings s;
  s.tangent_samples = {2, 3};
  s.xi_resolution = s.wo_resolution = 12;
  s.wi_resolution = 12;
  s.lambda_levels = 2;
  s.lambda_max = 8.0;
  const WeightingTables tb = bake_weighting_tables(satin, s);
  EXPECT_EQ(tb.sample_count(), 5);
  EXPECT_EQ(tb.distinct_count(), 3);
  EXPECT_EQ(tb.sample_table, (std::vector<int>{0, 1, 2, 2, 2}));
  EXPECT_EQ(&tb.table(2, 1), &tb.table(4, 1));
}
