// When a kiosk without a screen says so (kiosk/screen_wait.h), on a clock driven by the test:
// once after --display-wait seconds with none, from boot or from an unplug; again when one is
// back; never with a wait of 0.
#include <gtest/gtest.h>

#include "kiosk/screen_wait.h"

using namespace weft;
using Report = ScreenWait::Report;
using std::chrono::milliseconds;

namespace {
const ScreenWait::Clock::time_point t0{};
constexpr std::time_t kBootUtc = 1'800'000'000;
ScreenWait::Clock::time_point at(double s) { return t0 + milliseconds(long(s * 1000)); }
}  // namespace

TEST(ScreenWait, NeverAScreenIsReportedOnceAfterTheWait) {
  ScreenWait w(60, t0, kBootUtc);
  EXPECT_EQ(w.update(false, at(0.0), kBootUtc), Report::none);
  EXPECT_EQ(w.update(false, at(59.9), kBootUtc + 59), Report::none);
  EXPECT_FALSE(w.missing());
  EXPECT_EQ(w.update(false, at(60.0), kBootUtc + 60), Report::missing);
  EXPECT_TRUE(w.missing());
  EXPECT_EQ(w.none_since(), kBootUtc);  // since boot
  EXPECT_DOUBLE_EQ(w.seconds_without(at(60.0)), 60.0);
  for (double s = 61; s < 600; s += 17) EXPECT_EQ(w.update(false, at(s), kBootUtc + long(s)), Report::none) << s;
  EXPECT_EQ(w.update(true, at(700), kBootUtc + 700), Report::back);
  EXPECT_FALSE(w.missing());
  EXPECT_EQ(w.update(true, at(701), kBootUtc + 701), Report::none);
  EXPECT_DOUBLE_EQ(w.seconds_without(at(701)), 0.0);
}

TEST(ScreenWait, AScreenInTimeIsNeverReported) {
  ScreenWait w(60, t0, kBootUtc);
  EXPECT_EQ(w.update(false, at(30), kBootUtc + 30), Report::none);
  EXPECT_EQ(w.update(true, at(31), kBootUtc + 31), Report::none);  // not "back": nothing was reported
  EXPECT_EQ(w.update(true, at(500), kBootUtc + 500), Report::none);
}

TEST(ScreenWait, AnUnplugStartsTheWaitAgain) {
  ScreenWait w(10, t0, kBootUtc);
  EXPECT_EQ(w.update(true, at(1), kBootUtc + 1), Report::none);
  EXPECT_EQ(w.update(false, at(100), kBootUtc + 100), Report::none);  // unplugged at 100 s
  EXPECT_EQ(w.none_since(), kBootUtc + 100);
  EXPECT_EQ(w.update(false, at(109.9), kBootUtc + 109), Report::none);
  EXPECT_EQ(w.update(false, at(110), kBootUtc + 110), Report::missing);
  EXPECT_EQ(w.update(true, at(111), kBootUtc + 111), Report::back);
  // A screen back only for a moment: the next stretch is timed from its own start.
  EXPECT_EQ(w.update(false, at(112), kBootUtc + 112), Report::none);
  EXPECT_EQ(w.update(false, at(121.9), kBootUtc + 121), Report::none);
  EXPECT_EQ(w.update(false, at(122), kBootUtc + 122), Report::missing);
  EXPECT_EQ(w.none_since(), kBootUtc + 112);
}

TEST(ScreenWait, ZeroNeverReports) {
  ScreenWait w(0, t0, kBootUtc);
  for (double s = 0; s < 100000; s += 997) EXPECT_EQ(w.update(false, at(s), kBootUtc + long(s)), Report::none);
  EXPECT_FALSE(w.missing());
}
