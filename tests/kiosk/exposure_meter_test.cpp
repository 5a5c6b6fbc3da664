// The kiosk's exposure meter on synthetic frames whose cloth has a known log-average luminance:
// the target takes it to the key 0.5 (times 2^bias), the backdrop (alpha 0) never counts, and
// a new target is eased in as a first-order lag in log space.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "kiosk/exposure_meter.h"

namespace weft {
namespace {

// RGBA floats: grey cloth pixels (alpha 1) of the given values, and bright backdrop pixels (alpha 0).
std::vector<float> frame(const std::vector<float>& cloth_greys, int backdrop_pixels) {
  std::vector<float> rgba;
  for (float g : cloth_greys) rgba.insert(rgba.end(), {g, g, g, 1.0f});
  for (int i = 0; i < backdrop_pixels; ++i) rgba.insert(rgba.end(), {50.0f, 60.0f, 70.0f, 0.0f});
  return rgba;
}

TEST(ExposureMeter, TakesTheClothsLogAverageToTheKeyAndIgnoresTheBackdrop) {
  ExposureMeter m(0.0, 0.7);
  EXPECT_EQ(m.shown(), 0.0);
  // Log-average of 0.1 and 0.4 is 0.2: exposure 0.5 / 0.2.
  m.meter(frame({0.1f, 0.4f, 0.1f, 0.4f}, 12));
  EXPECT_NEAR(m.target(), 2.5, 1e-6);
  EXPECT_NEAR(m.shown(), 2.5, 1e-6);  // the first metering is shown at once
}

// A driver's NaN on the cloth: counted, left out of the average (the rest meters as it would alone).
TEST(ExposureMeter, CountsClothPixelsThatAreNotFiniteAndMetersWithoutThem) {
  ExposureMeter clean(0.0, 0.7), with_nan(0.0, 0.7);
  clean.meter(frame({0.1f, 0.4f}, 4));
  std::vector<float> f = frame({0.1f, 0.4f, 0.3f, 0.3f}, 4);
  f[8] = std::nanf("");                            // third cloth pixel's red
  f[13] = std::numeric_limits<float>::infinity();  // fourth's green
  f[16 + 1] = std::nanf("");                       // a backdrop pixel: not cloth, not counted
  with_nan.meter(f);
  EXPECT_EQ(clean.non_finite_pixels(), 0u);
  EXPECT_EQ(with_nan.cloth_pixels(), 4u);
  EXPECT_EQ(with_nan.non_finite_pixels(), 2u);
  EXPECT_NEAR(with_nan.target(), clean.target(), 1e-9);
}

TEST(ExposureMeter, TheBiasIsInStops) {
  ExposureMeter brighter(1.0, 0.7), darker(-2.0, 0.7);
  brighter.meter(frame({0.25f}, 3));
  darker.meter(frame({0.25f}, 3));
  EXPECT_NEAR(brighter.target(), 2.0 * 2.0, 1e-6);
  EXPECT_NEAR(darker.target(), 2.0 / 4.0, 1e-6);
}

TEST(ExposureMeter, ARequestIsClearedByTheMetering) {
  ExposureMeter m(0.0, 0.7);
  EXPECT_FALSE(m.requested());
  m.request();
  EXPECT_TRUE(m.requested());
  m.meter(frame({0.5f}, 0));
  EXPECT_FALSE(m.requested());
}

TEST(ExposureMeter, ANewTargetEasesInAndRestartShowsItAtOnce) {
  const double tau = 0.7;
  ExposureMeter m(0.0, tau);
  const auto t0 = std::chrono::steady_clock::time_point(std::chrono::hours(1));
  m.meter(frame({0.2f}, 4));  // 2.5
  m.ease(t0);
  EXPECT_NEAR(m.shown(), 2.5, 1e-6);
  EXPECT_FALSE(m.adapting());

  m.meter(frame({0.05f}, 4));  // target 10, shown stays
  EXPECT_NEAR(m.target(), 10.0, 1e-5);
  EXPECT_NEAR(m.shown(), 2.5, 1e-6);
  EXPECT_TRUE(m.adapting());
  // One time constant later: 1 − 1/e of the way in log space.
  m.ease(t0 + std::chrono::milliseconds(700));
  const double expected = std::exp(std::log(2.5) + (1.0 - std::exp(-1.0)) * (std::log(10.0) - std::log(2.5)));
  EXPECT_NEAR(m.shown(), expected, 1e-5);
  EXPECT_TRUE(m.adapting());
  m.ease(t0 + std::chrono::seconds(60));
  EXPECT_NEAR(m.shown(), 10.0, 1e-4);
  EXPECT_FALSE(m.adapting());

  m.restart();
  m.meter(frame({0.2f}, 4));
  EXPECT_NEAR(m.shown(), 2.5, 1e-6);
}

}  // namespace
}  // namespace weft
