// The per-vertex visibility mask (runtime/visibility_mask.h): its cells are of equal solid angle
// over the upper hemisphere, and the open share of an SG it gives matches closed forms: a
// horizon raised to height h cuts ∫_{z>h} e^{λ(z−1)} dω = 2π(1 − e^{λ(h−1)})/λ out of the
// hemisphere's 2π(1 − e^{−λ})/λ for an SG at the zenith.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "runtime/visibility_mask.h"

using namespace weft;

namespace {

// One vertex whose cells are open where `open(direction)` holds.
template <class F>
VisibilityMask one_vertex(int n, F open) {
  VisibilityMask m;
  m.resolution = n;
  m.words.assign(size_t(m.blocks()), 0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      if (open(hemisphere_cell_direction(n, x, y))) m.set_open(0, x, y);
  return m;
}

TEST(VisibilityMask, CellsCoverTheHemisphereAtEqualSolidAngle) {
  // Over the hemisphere E[z] = 1/2 and E[z²] = 1/3 under equal solid angle; an unequal map weights
  // the cells' centres otherwise.
  const int n = 64;
  double z1 = 0, z2 = 0, x1 = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::dvec3 d = hemisphere_cell_direction(n, x, y);
      ASSERT_NEAR(glm::length(d), 1.0, 1e-12);
      ASSERT_GE(d.z, 0.0);
      z1 += d.z, z2 += d.z * d.z, x1 += d.x;
    }
  EXPECT_NEAR(z1 / (n * n), 0.5, 1e-3);
  EXPECT_NEAR(z2 / (n * n), 1.0 / 3.0, 1e-3);
  EXPECT_NEAR(x1 / (n * n), 0.0, 1e-9);
}

TEST(VisibilityMask, OpenShareOfAnSgMatchesARaisedHorizon) {
  const int n = 64;
  const double h = std::sin(glm::radians(10.0));
  const VisibilityMask m = one_vertex(n, [&](const glm::dvec3& d) { return d.z > h; });
  const MaskDirections dirs(n);
  for (double lambda : {0.5, 1.0, 4.0, 20.0, 100.0}) {
    const double want = -std::expm1(lambda * (h - 1.0)) / -std::expm1(-lambda);
    const double got = dirs.sg_open_share(m, 0, glm::dvec3(0, 0, 1), lambda);
    // The boundary runs through cells ≈ 2.2° wide: a share of a cell row's weight.
    EXPECT_NEAR(got, want, 0.01) << "λ = " << lambda;
  }
  // A sun well above the raised horizon is open, one well below it blocked, one on it half open.
  auto at = [](double elevation_deg) {
    const double e = glm::radians(elevation_deg);
    return glm::dvec3(std::cos(e) * 0.6, std::cos(e) * 0.8, std::sin(e));
  };
  EXPECT_NEAR(dirs.sg_open_share(m, 0, at(25), 1000.0), 1.0, 1e-6);
  EXPECT_NEAR(dirs.sg_open_share(m, 0, at(3), 1000.0), 0.0, 1e-4);  // its tail 7° up: e^{−7.5} per cell
  EXPECT_NEAR(dirs.sg_open_share(m, 0, at(10), 1000.0), 0.5, 0.15);
}

// The grouped sum against Σ bit·G / Σ G over every single cell, in double, on a wrinkled horizon
// with a blocked cap: within 0.005 of the share for lobes of λ 0.5 … 1000 that have weight above
// the surface.
TEST(VisibilityMask, GroupedSumMatchesTheCellSum) {
  const int n = 64;
  const glm::dvec3 cap = glm::normalize(glm::dvec3(0.5, -0.3, 0.6));
  const VisibilityMask m = one_vertex(n, [&](const glm::dvec3& d) {
    const double phi = std::atan2(d.y, d.x);
    return d.z > 0.15 + 0.12 * std::sin(3.0 * phi) && glm::dot(d, cap) < std::cos(glm::radians(20.0));
  });
  const MaskDirections dirs(n);
  int compared = 0;
  for (double lambda : {0.5, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0})
    for (double elevation : {-3.0, 2.0, 10.0, 20.0, 35.0, 60.0, 85.0})
      for (double azimuth : {0.0, 50.0, 125.0, 200.0, 330.0}) {
        const double e = glm::radians(elevation), a = glm::radians(azimuth);
        const glm::dvec3 axis(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
        double open = 0, all = 0, top = -1e300;
        for (int y = 0; y < n; ++y)
          for (int x = 0; x < n; ++x) {
            const double t = lambda * (glm::dot(hemisphere_cell_direction(n, x, y), axis) - 1.0);
            top = std::max(top, t);
            all += std::exp(t);
            if (m.open(0, x, y)) open += std::exp(t);
          }
        if (top < -14.0) continue;  // no weight above the surface
        EXPECT_NEAR(dirs.sg_open_share(m, 0, axis, lambda), open / all, 0.005)
            << "λ " << lambda << ", elevation " << elevation << "°, azimuth " << azimuth << "°";
        ++compared;
      }
  EXPECT_GT(compared, 250);
}

TEST(VisibilityMask, AllOpenAndAllBlocked) {
  const MaskDirections dirs(16);
  const VisibilityMask open = one_vertex(16, [](const glm::dvec3&) { return true; });
  const VisibilityMask blocked = one_vertex(16, [](const glm::dvec3&) { return false; });
  for (const glm::dvec3& axis : {glm::dvec3(0, 0, 1), glm::normalize(glm::dvec3(1, 0.3, 0.05)), glm::dvec3(0, 0, -1)})
    for (double lambda : {0.3, 8.0, 500.0}) {
      EXPECT_DOUBLE_EQ(dirs.sg_open_share(open, 0, axis, lambda), 1.0);
      // A lobe with no weight above the surface counts as open (1); any other is fully blocked.
      const double b = dirs.sg_open_share(blocked, 0, axis, lambda);
      EXPECT_TRUE(b == 0.0 || (axis.z < 0 && lambda > 100)) << b;
    }
}

}  // namespace

// hemisphere_cell_of inverts the map: every cell's centre, and points near its corners, land in
// that cell (the broad lobes' quadrature finds its directions' bits this way).
TEST(VisibilityMask, CellOfADirectionInvertsTheMap) {
  for (int n : {8, 64}) {
    int wrong = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        if (hemisphere_cell_of(n, hemisphere_cell_direction(n, x, y)) != y * n + x) ++wrong;
        for (double dx : {-0.45, 0.45})
          for (double dy : {-0.45, 0.45}) {
            const glm::dvec3 d = hemisphere_square_direction((2.0 * (x + 0.5 + dx)) / n - 1.0, (2.0 * (y + 0.5 + dy)) / n - 1.0);
            if (hemisphere_cell_of(n, d) != y * n + x) ++wrong;
          }
      }
    EXPECT_EQ(wrong, 0) << "resolution " << n;
  }
}
