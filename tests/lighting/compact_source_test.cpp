// render/lighting: the dominant compact source of a map — a small disc on a dim sky is found at
// its centre with its power (the disc's solid angle times its radiance above the sky, both
// known in closed form), and the map without it keeps the rest; broad or faint bright
// patches and a uniform map are not compact sources.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "lighting/compact_source.h"

using namespace weft;
using glm::dvec3;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// A sky of constant radiance `sky` with a disc of angular radius `radius_deg` and radiance
// `sky + disc` around `centre`; texels near the disc are supersampled (in solid angle) finely
// enough to hold its area to a fraction of a percent.
EnvMap disc_map(int width, const dvec3& centre, double radius_deg, double sky, double disc) {
  EnvMap m(width, width / 2);
  const double r = radius_deg * kDeg, cos_r = std::cos(r), texel = kPi / m.height;
  const double cos_near = std::cos(std::min(kPi, r + 2.0 * texel));
  const int n = std::clamp(static_cast<int>(std::ceil(16.0 * texel / std::max(r, 1e-3))), 16, 256);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      double inside = 0.0, total = 1.0;
      if (glm::dot(m.direction(x, y), centre) >= cos_near) {
        total = 0.0;
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) {
            const dvec3 d = uv_to_direction({(x + (i + 0.5) / n) / m.width, 1.0 - (y + (j + 0.5) / n) / m.height});
            const double w = std::sqrt(std::max(0.0, 1.0 - d.z * d.z));
            total += w;
            if (glm::dot(d, centre) >= cos_r) inside += w;
          }
      }
      m.at(x, y) = glm::vec3(static_cast<float>(sky + disc * inside / total));
    }
  return m;
}

double angle_deg(const dvec3& a, const dvec3& b) { return std::acos(std::min(1.0, glm::dot(a, b))) / kDeg; }
}  // namespace

TEST(CompactSource, ASmallDiscIsFoundAtItsCentreWithItsPower) {
  const dvec3 centre = glm::normalize(dvec3(0.4, 0.7, 0.35));
  for (int width : {128, 512})
    for (double radius : {0.5, 2.5}) {
      const EnvMap map = disc_map(width, centre, radius, 0.5, 2000.0);
      EnvMap rest;
      const auto s = find_compact_source(map, {}, &rest);
      ASSERT_TRUE(s.has_value()) << width << " " << radius;
      const double expected = 2000.0 * 2.0 * kPi * (1.0 - std::cos(radius * kDeg));
      EXPECT_NEAR(s->power.g / expected, 1.0, 0.02) << width << " " << radius;
      // Within a fraction of a texel of the centre (a sub-texel disc sits at its texels' centroid).
      EXPECT_LT(angle_deg(s->direction, centre), 0.3 * 180.0 / (width / 2)) << width << " " << radius;
      EXPECT_NEAR(s->background.g, 0.5, 0.05);
      // The map without the source holds the rest of the power: the sky's 4π · 0.5 (to the
      // background's estimate over the disc).
      double sum = 0.0;
      for (int y = 0; y < rest.height; ++y)
        for (int x = 0; x < rest.width; ++x) sum += rest.solid_angle(y) * rest.at(x, y).g;
      EXPECT_NEAR(sum / (4.0 * kPi * 0.5), 1.0, 0.01) << width << " " << radius;
    }
  // A disc of 2.5° radius: spread r²/4 to within the map's discretisation.
  const auto s = find_compact_source(disc_map(512, centre, 2.5, 0.5, 2000.0));
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->spread / (std::pow(2.5 * kDeg, 2) / 4.0), 1.0, 0.1);
}

TEST(CompactSource, BroadFaintAndUniformMapsHaveNone) {
  const dvec3 centre = glm::normalize(dvec3(-0.3, 0.2, 0.6));
  EXPECT_FALSE(find_compact_source(disc_map(256, centre, 15.0, 0.5, 2000.0)).has_value()) << "broad";
  EXPECT_FALSE(find_compact_source(disc_map(256, centre, 1.0, 0.5, 2.0)).has_value()) << "low contrast";
  // Bright but carrying a tiny share of the map's power.
  EXPECT_FALSE(find_compact_source(disc_map(256, centre, 0.3, 50.0, 2000.0)).has_value()) << "faint";
  EXPECT_FALSE(find_compact_source(disc_map(128, centre, 0.0, 1.0, 0.0)).has_value()) << "uniform";
  EXPECT_FALSE(find_compact_source(EnvMap(64, 32)).has_value()) << "black";
}
