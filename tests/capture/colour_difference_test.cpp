// The thread-colour measure: CIE L*a*b* from linear sRGB against its closed form, and CIEDE2000
// against Sharma, Wu and Dalal's published test data (Color Res. Appl. 30(1), 2005, Table 1),
// including the pairs either side of the mean-hue discontinuity at 180°.
#include <gtest/gtest.h>

#include <cmath>

#include "capture/appearance_check.h"
#include "capture/colour_difference.h"
#include "core/fabric.h"

namespace {

using weft::Lab;

TEST(ColourDifference, LabOfGreysFollowsTheLightnessCurve) {
  // Neutral greys have a* = b* = 0 and L* = 116 Y^(1/3) − 16 (Y > 216/24389), 903.3 Y below.
  for (double y : {1.0, 0.18, 0.05}) {
    const Lab c = weft::lab_from_linear_srgb({y, y, y});
    EXPECT_NEAR(c.L, 116 * std::cbrt(y) - 16, 1e-3) << y;
    EXPECT_NEAR(c.a, 0, 1e-3) << y;
    EXPECT_NEAR(c.b, 0, 1e-3) << y;
  }
  EXPECT_NEAR(weft::lab_from_linear_srgb({0.001, 0.001, 0.001}).L, 24389.0 / 27.0 * 0.001, 1e-3);
  // Pure sRGB red: L* 53.24, a* 80.09, b* 67.20 (D65).
  const Lab red = weft::lab_from_linear_srgb({1, 0, 0});
  EXPECT_NEAR(red.L, 53.24, 0.01);
  EXPECT_NEAR(red.a, 80.09, 0.01);
  EXPECT_NEAR(red.b, 67.20, 0.01);
}

TEST(ColourDifference, SharmaTestData) {
  struct Pair {
    Lab x, y;
    double de;
  };
  const Pair pairs[] = {
      {{50, 2.6772, -79.7751}, {50, 0, -82.7485}, 2.0425},        // 1
      {{50, 0, 0}, {50, -1, 2}, 2.3669},                          // 7
      {{50, 2.49, -0.001}, {50, -2.49, 0.0009}, 7.1792},          // 12
      {{50, 2.49, -0.001}, {50, -2.49, 0.0011}, 7.2195},          // 14
      {{50, 2.5, 0}, {73, 25, -18}, 27.1492},                     // 17
      {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},  // 19
      {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},  // 24
      {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},       // 34
  };
  for (const Pair& p : pairs) {
    EXPECT_NEAR(weft::delta_e2000(p.x, p.y), p.de, 1e-4);
    EXPECT_NEAR(weft::delta_e2000(p.y, p.x), p.de, 1e-4);  // symmetric
  }
}

TEST(ColourDifference, ThreadColoursAreComparedAsTheModelReadsThem) {
  const weft::Fabric truth = weft::load_fabric_preset("silk_shot", WEFT_SOURCE_ASSETS "/fabrics");
  EXPECT_EQ(weft::thread_delta_e2000(truth, truth), (std::array<double, 2>{0, 0}));
  weft::Fabric fitted = truth;
  fitted.threads[1].albedo *= 1.2;  // only the second thread's colour moves
  const std::array<double, 2> de = weft::thread_delta_e2000(truth, fitted);
  EXPECT_EQ(de[0], 0);
  EXPECT_NEAR(de[1], weft::delta_e2000(truth.threads[1].albedo, truth.threads[1].albedo * 1.2), 1e-12);
  EXPECT_GT(de[1], 1.0);
}

}  // namespace
