// The display operator's closed forms: Hable's curve (zero at zero, increasing, white point),
// sRGB encoding at its defining points, metering (a uniform cloth lands on the key) and the
// exposure easing's first-order lag.
#include <gtest/gtest.h>

#include <cmath>

#include "image/image.h"
#include "image/tone_map.h"

using namespace weft;

namespace {
// Hable's rational curve written out from the published constants (A..F, W = 11.2), not from
// kFilmicCurve, so that a changed constant shows here.
double hable_published(double x) {
  const double A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30;
  return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}
}  // namespace

TEST(ToneCurve, ZeroAtZeroWhiteAtWhitePointAndMatchesThePublishedFit) {
  EXPECT_EQ(filmic_curve(0.0), 0.0);
  EXPECT_EQ(filmic_curve(-1.0), 0.0);
  EXPECT_EQ(filmic_curve(std::nan("")), 0.0);
  EXPECT_NEAR(filmic_curve(11.2), 1.0, 1e-12);
  EXPECT_EQ(filmic_curve(50.0), 1.0);  // past the white point: clipped, not above 1
  for (double x : {0.01, 0.18, 0.5, 1.0, 4.0})
    EXPECT_NEAR(filmic_curve(x), hable_published(x) / hable_published(11.2), 1e-12) << x;
  // The toe: near 0 the slope is h'(0)/h(W) = (C·B·D·F − D·E·B)/(D·F)² / h(W).
  const double slope0 = (0.10 * 0.50 * 0.20 * 0.30 - 0.20 * 0.02 * 0.50) / std::pow(0.20 * 0.30, 2) / hable_published(11.2);
  EXPECT_NEAR(filmic_curve(1e-7) / 1e-7, slope0, 1e-4 * slope0);
}

TEST(ToneCurve, IncreasesStrictlyUpToTheWhitePoint) {
  double last = 0.0;
  for (int i = 1; i <= 2000; ++i) {
    const double x = 11.2 * i / 2000.0;
    const double y = filmic_curve(x);
    EXPECT_GT(y, last) << x;
    last = y;
  }
}

TEST(ToneCurve, SrgbEncodeAtItsDefiningPoints) {
  EXPECT_EQ(srgb_encode(0.0), 0.0);
  EXPECT_NEAR(srgb_encode(1.0), 1.0, 1e-12);
  EXPECT_NEAR(srgb_encode(0.002), 12.92 * 0.002, 1e-15);             // linear segment
  EXPECT_NEAR(srgb_encode(0.5), 1.055 * std::pow(0.5, 1 / 2.4) - 0.055, 1e-15);
  EXPECT_NEAR(srgb_encode(0.0031308), 0.0404500, 2e-6);               // the two pieces meet
  EXPECT_EQ(srgb_encode(2.0), srgb_encode(1.0));  // clamped
  EXPECT_EQ(srgb_encode(std::nan("")), 0.0);
  EXPECT_NEAR(display_value(0.25, 2.0), srgb_encode(filmic_curve(0.5)), 1e-15);
}

TEST(Metering, UniformClothRadianceLandsOnTheKey) {
  for (double L : {0.003, 0.1, 2.0, 75.0}) {
    Image img(8, 6);
    std::vector<bool> cloth(img.pixels.size(), false);
    for (size_t i = 0; i < img.pixels.size(); ++i)
      if (i % 3 == 0) img.pixels[i] = glm::dvec3(L), cloth[i] = true;
      else img.pixels[i] = glm::dvec3(1000.0 * (i % 5));  // backdrop and floor: not metered
    const double e = auto_exposure(img, cloth);
    EXPECT_NEAR(e * L, kMeteringKey, 1e-12 * kMeteringKey) << L;
    EXPECT_NEAR(auto_exposure(img, cloth, 1.5) * L, kMeteringKey * std::pow(2.0, 1.5), 1e-11) << L;
  }
}

TEST(Metering, LogAverageIsTheGeometricMeanOfLuminance) {
  // Two cloth pixels of grey 0.5 and 8 → geometric mean 2; a coloured pixel counts by its
  // Rec. 709 luminance; black pixels count as the floor.
  EXPECT_NEAR(log_average_luminance({glm::dvec3(0.5), glm::dvec3(8.0)}), 2.0, 1e-12);
  EXPECT_NEAR(log_average_luminance({glm::dvec3(1, 0, 0)}), 0.2126, 1e-12);
  EXPECT_NEAR(log_average_luminance({glm::dvec3(0.0), glm::dvec3(1.0)}), std::sqrt(kMeteringFloor), 1e-15);
  EXPECT_EQ(log_average_luminance({}), 0.0);
  EXPECT_EQ(metered_exposure(0.0, 2.0), 4.0);  // nothing metered: the bias alone
}

TEST(Metering, AdaptationIsAFirstOrderLagInLogExposure) {
  const double tau = 0.7;
  // After one time constant, 1 − 1/e of the way in log space.
  const double e = adapt_exposure(1.0, 8.0, tau, tau);
  EXPECT_NEAR(std::log(e), (1 - std::exp(-1.0)) * std::log(8.0), 1e-12);
  // Steps compose: two half steps equal one whole step.
  EXPECT_NEAR(adapt_exposure(adapt_exposure(1.0, 8.0, tau / 2, tau), 8.0, tau / 2, tau), e, 1e-12);
  EXPECT_EQ(adapt_exposure(0.0, 3.0, 0.01, tau), 3.0);  // nothing shown yet: straight to the target
}

TEST(ToneCurve, GlslDefinesCarryEveryConstant) {
  const std::string d = tone_map_glsl_defines();
  for (const char* name : {"A 0.15", "B 0.5", "C 0.1", "D 0.2", "E 0.02", "F 0.3", "W 11.2"})
    EXPECT_NE(d.find(std::string("#define WEFT_FILMIC_") + name + "\n"), std::string::npos) << name << "\n" << d;
}
