// SDF of binary visibility: the exact distance transform against brute force,
// the paper's signed-distance formula, gradients, and the per-vertex pipeline.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <cstdio>
#include <random>

#include "bake/visibility/visibility_sdf.h"

using namespace weft;

namespace {

constexpr double kPi = std::numbers::pi;

// Brute-force squared distance to the nearest feature cell (periodic columns optional).
double brute_squared(const std::vector<uint8_t>& f, int rows, int cols, bool periodic, int i,
                     int j) {
  double best = std::numeric_limits<double>::infinity();
  for (int a = 0; a < rows; ++a)
    for (int b = 0; b < cols; ++b) {
      if (!f[size_t(a) * cols + b]) continue;
      double dj = std::abs(b - j);
      if (periodic) dj = std::min(dj, cols - dj);
      best = std::min(best, double(a - i) * (a - i) + dj * dj);
    }
  return best;
}

}  // namespace

TEST(DistanceTransform, ExactAgainstBruteForceOnRandomGrids) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 24; ++trial) {
    const int rows = 1 + int(rng() % 23), cols = 1 + int(rng() % 31);
    const double density = std::array{0.01, 0.05, 0.3, 0.7}[trial % 4];
    const bool periodic = trial % 2;
    std::bernoulli_distribution coin(density);
    std::vector<uint8_t> f(size_t(rows) * cols);
    for (auto& x : f) x = coin(rng);
    const auto got = squared_distance_transform(f, rows, cols, periodic);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) {
        const double want = brute_squared(f, rows, cols, periodic, i, j);
        const double have = got[size_t(i) * cols + j];
        if (std::isinf(want)) EXPECT_TRUE(std::isinf(have));
        else EXPECT_EQ(have, want) << "trial " << trial << " cell " << i << "," << j;
      }
  }
}

TEST(DistanceTransform, PeriodicWrapFindsFeatureAcrossTheSeam) {
  // One feature in the last column: the first column is 1 away only with φ periodic.
  std::vector<uint8_t> f(3 * 10, 0);
  f[1 * 10 + 9] = 1;
  EXPECT_EQ(squared_distance_transform(f, 3, 10, true)[1 * 10 + 0], 1.0);
  EXPECT_EQ(squared_distance_transform(f, 3, 10, false)[1 * 10 + 0], 81.0);
}

TEST(SignedDistance, MatchesThePapersFormulaOnRandomGrids) {
  std::mt19937 rng(7);
  const int rows = 16, cols = 32;
  const double h = kPi / rows;
  VisibilityGrid v{rows, cols, std::vector<uint8_t>(rows * cols)};
  std::bernoulli_distribution coin(0.4);
  for (auto& x : v.values) x = coin(rng);
  const DistanceGrid d = signed_distance(v, h, true, false);
  const DistanceGrid d_off = signed_distance(v, h, true, true);
  std::vector<uint8_t> visible(v.values), occluded(v.values.size());
  for (size_t k = 0; k < occluded.size(); ++k) occluded[k] = !visible[k];
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      // d = +min over V = 0 of the angular distance where V = 1, −min over V = 1 elsewhere.
      const bool vis = v.at(i, j);
      const double want =
          (vis ? 1 : -1) * std::sqrt(brute_squared(vis ? occluded : visible, rows, cols, true, i, j)) * h;
      EXPECT_NEAR(d.at(i, j), want, 1e-12);
      EXPECT_NEAR(d_off.at(i, j), want - (vis ? 0.5 : -0.5) * h, 1e-12);
    }
}

TEST(SignedDistance, HalfPlaneIsExactAndItsGradientPointsAcrossTheBoundary) {
  // V = [θ > 0] on the full φ circle: d(θ, φ) = θ and ∇d = (1, 0).
  const int n = 64;
  const double h = kPi / n;
  VisibilityGrid v{n, 2 * n, std::vector<uint8_t>(2 * n * n)};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) v.at(i, j) = cell_centre(-kPi / 2, h, i) > 0;
  const DistanceGrid d = signed_distance(v, h, true, true);
  const SdfGradient g = sdf_gradient(d, h, true);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      EXPECT_NEAR(d.at(i, j), cell_centre(-kPi / 2, h, i), 1e-12);
      EXPECT_NEAR(g.d_theta.at(i, j), 1.0, 1e-9);
      EXPECT_NEAR(g.d_phi.at(i, j), 0.0, 1e-9);
    }
}

TEST(SignedDistance, TiltedHalfPlaneGradientFollowsTheLineNormal) {
  // V = [a·θ + b·φ > 0]: away from the poles, the seam and the medial axis, ∇d ∥ (a, b).
  const int n = 128;
  const double h = kPi / n;
  const double a = std::cos(0.6), b = std::sin(0.6);
  VisibilityGrid v{n, n, std::vector<uint8_t>(n * n)};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      v.at(i, j) = a * cell_centre(-kPi / 2, h, i) + b * cell_centre(-kPi / 2, h, j) > 0;
  const DistanceGrid d = signed_distance(v, h, false, true);
  const SdfGradient g = sdf_gradient(d, h, false);
  double worst_angle = 0, worst_distance = 0, sum_angle = 0;
  int count = 0;
  for (int i = 8; i < n - 8; ++i)
    for (int j = 8; j < n - 8; ++j) {
      const double theta = cell_centre(-kPi / 2, h, i), phi = cell_centre(-kPi / 2, h, j);
      const double exact = a * theta + b * phi;  // signed distance to the line
      if (std::abs(exact) > 0.5) continue;  // stay within reach of the line, not the edges
      worst_distance = std::max(worst_distance, std::abs(d.at(i, j) - exact));
      if (std::abs(exact) < 3 * h) continue;  // the staircase itself
      const double gt = g.d_theta.at(i, j), gp = g.d_phi.at(i, j);
      const double angle = std::acos(std::clamp((gt * a + gp * b) / std::hypot(gt, gp), -1.0, 1.0));
      worst_angle = std::max(worst_angle, angle);
      sum_angle += angle;
      ++count;
    }
  std::printf("  tilted half-plane: |d − exact| ≤ %.4f (h = %.4f), ∇d angle mean %.2f° max %.2f°\n",
              worst_distance, h, sum_angle / count * 180 / kPi, worst_angle * 180 / kPi);
  // A sampled line is a staircase: distances are exact to a cell, directions to a few degrees
  // (central differences of a staircase; the paper box-filters 512² down to 128²).
  EXPECT_LT(worst_distance, h);
  EXPECT_LT(sum_angle / count, 5.0 * kPi / 180);  // measured 3.6° at 128² (1 sample per cell)
  EXPECT_LT(worst_angle, 15.0 * kPi / 180);
}

TEST(VertexSdf, OpenSkyMeasuresTheDistanceToTheHorizon) {
  // Nothing occludes: only the surface itself does, so d(θ, φ) = π/2 − |φ| on the hemisphere.
  const SurfaceFrame frame;
  int casts = 0;
  auto never = [&](const dvec3&, const dvec3& dir) {
    ++casts;
    EXPECT_GT(dir.z, 0.0);  // below-horizon directions are not cast
    return false;
  };
  for (int s : {1, 2}) {
    casts = 0;
    const VertexSdf sdf = vertex_sdf(frame, dvec3(0), 32, s, never);
    EXPECT_EQ(casts, 32 * s * 32 * s);
    ASSERT_EQ(sdf.d.rows, 32);
    ASSERT_EQ(sdf.d.cols, 32);
    for (int i = 0; i < 32; ++i)
      for (int j = 0; j < 32; ++j)
        EXPECT_NEAR(sdf.d.at(i, j), kPi / 2 - std::abs(cell_centre(-kPi / 2, sdf.h, j)), 1e-12);
  }
}

TEST(VertexSdf, EqualsTheFullPeriodicCircleCropped) {
  // vertex_sdf frames the hemisphere with the horizon instead of transforming the whole circle.
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  dvec3 m[3];
  for (auto& x : m) x = glm::normalize(dvec3(u(rng), u(rng), u(rng)));
  auto occluded = [&](const dvec3&, const dvec3& w) {
    return glm::dot(w, m[0]) > 0.6 || glm::dot(w, m[1]) > 0.7 || std::sin(9 * w.x) * w.y > 0.2;
  };
  const int n = 48;
  const VertexSdf sdf = vertex_sdf(SurfaceFrame{}, dvec3(0), n, 1, occluded);
  const DistanceGrid full = hemisphere_crop(
      signed_distance(sample_visibility(SurfaceFrame{}, dvec3(0), n, occluded), kPi / n, true, true));
  ASSERT_EQ(full.values.size(), sdf.d.values.size());
  for (size_t k = 0; k < full.values.size(); ++k) EXPECT_DOUBLE_EQ(sdf.d.values[k], full.values[k]);
}

TEST(VertexSdf, DirectionsFollowTheThreadFrameAngles) {
  // ω(θ, φ) must give back θ, φ through the canonical model's fiber_angles (α = 0, thread 1).
  const SurfaceFrame frame = SurfaceFrame::from_normal_warp(glm::normalize(dvec3(0.2, -0.1, 1)), dvec3(1, 0.3, 0));
  const ThreadFrame tf = thread_frame(frame, 0, 0.0);
  for (double theta : {-1.2, -0.3, 0.0, 0.7})
    for (double phi : {-1.4, -0.2, 0.5, 1.1}) {
      const FiberAngles fa = fiber_angles(tf, direction_from_angles(frame, theta, phi));
      EXPECT_NEAR(fa.theta, theta, 1e-12);
      EXPECT_NEAR(fa.phi, phi, 1e-12);
    }
}

TEST(VertexSdf, RejectsBadSettings) {
  auto never = [](const dvec3&, const dvec3&) { return false; };
  EXPECT_THROW(vertex_sdf(SurfaceFrame{}, dvec3(0), 31, 1, never), std::invalid_argument);
  EXPECT_THROW(vertex_sdf(SurfaceFrame{}, dvec3(0), 32, 0, never), std::invalid_argument);
  EXPECT_THROW(squared_distance_transform({1, 0}, 3, 3, false), std::invalid_argument);
}
