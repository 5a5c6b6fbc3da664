// The knobs' way home (kiosk/idle_return.h) and the screen's sleep (kiosk/screen_schedule.h).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "kiosk/idle_return.h"
#include "kiosk/screen_schedule.h"
#include "panel/appearance_blend.h"

using namespace weft;
using Clock = std::chrono::steady_clock;

namespace {
input::AppearanceState look(float r, float gloss, float rotation, float zoom) {
  input::AppearanceState s;
  for (auto& t : s.thread) {
    t.albedo[0] = r;
    t.albedo[1] = 0.2f;
    t.albedo[2] = 0.1f;
    t.gamma_scale = gloss;
  }
  s.env_rotation_deg = rotation;
  s.zoom = zoom;
  return s;
}
}  // namespace

TEST(IdleReturn, BlendIsLinearInColourGeometricInGlossShortArcInTurn) {
  const input::AppearanceState a = look(0.8f, 4.0f, 350.0f, 1.0f), b = look(0.2f, 1.0f, 10.0f, 0.0f);
  const input::AppearanceState h = input::blend_appearance(a, b, 0.5);
  EXPECT_NEAR(h.thread[0].albedo[0], 0.5, 1e-6);
  EXPECT_NEAR(h.thread[1].gamma_scale, 2.0, 1e-6);  // √(4·1)
  EXPECT_NEAR(h.env_rotation_deg, 0.0, 1e-4);       // 350° → 10° through 0°, not through 180°
  EXPECT_NEAR(h.zoom, 0.5, 1e-6);
  EXPECT_EQ(input::blend_appearance(a, b, 0.0), a);
  EXPECT_EQ(input::blend_appearance(a, b, 1.0), b);
  // Another fabric cannot be blended: home at once.
  input::AppearanceState other = a;
  other.preset_index = 3;
  EXPECT_EQ(input::blend_appearance(other, b, 0.3), b);
}

TEST(IdleReturn, EasesHomeAfterTheIdleTimeAndOnlyThen) {
  IdleReturn idle(60.0, 3.0);
  const Clock::time_point t0 = Clock::now();
  EXPECT_FALSE(idle.due(t0 + std::chrono::hours(1)));  // nothing touched: nothing to return from
  idle.touched(t0);
  EXPECT_FALSE(idle.due(t0 + std::chrono::seconds(59)));
  EXPECT_TRUE(idle.due(t0 + std::chrono::seconds(60)));
  idle.touched(t0 + std::chrono::seconds(30));  // a person again: the wait starts over
  EXPECT_FALSE(idle.due(t0 + std::chrono::seconds(60)));
  const Clock::time_point t1 = t0 + std::chrono::seconds(90);
  ASSERT_TRUE(idle.due(t1));
  const input::AppearanceState from = look(0.8f, 4.0f, 90.0f, 1.0f), home = look(0.2f, 1.0f, 0.0f, 0.0f);
  idle.start(from, home, t1);
  EXPECT_FALSE(idle.due(t1 + std::chrono::seconds(600)));  // on its way, then home: not again
  auto first = idle.step(t1);
  ASSERT_TRUE(first);
  EXPECT_EQ(*first, from);  // leaves from what was shown: no jump
  auto mid = idle.step(t1 + std::chrono::milliseconds(1500));
  ASSERT_TRUE(mid);
  EXPECT_NEAR(mid->thread[0].albedo[0], 0.5, 1e-5);  // smoothstep's midpoint is the midpoint
  auto last = idle.step(t1 + std::chrono::seconds(3));
  ASSERT_TRUE(last);
  EXPECT_EQ(*last, home);
  EXPECT_FALSE(idle.step(t1 + std::chrono::seconds(4)));  // arrived: nothing more to draw
  // Already home: no ease at all.
  idle.touched(t1 + std::chrono::seconds(5));
  idle.start(home, home, t1 + std::chrono::seconds(100));
  EXPECT_FALSE(idle.step(t1 + std::chrono::seconds(100)));
}

TEST(IdleReturn, NeverWhenOff) {
  IdleReturn idle(0.0, 3.0);
  const Clock::time_point t0 = Clock::now();
  idle.touched(t0);
  EXPECT_FALSE(idle.due(t0 + std::chrono::hours(48)));
}

TEST(ScreenSchedule, OffPeriodsByDayAndPastMidnight) {
  const ScreenSchedule day = ScreenSchedule::parse("12:30-13:00");
  EXPECT_FALSE(day.off_at(12 * 60 + 29));
  EXPECT_TRUE(day.off_at(12 * 60 + 30));
  EXPECT_TRUE(day.off_at(12 * 60 + 59));
  EXPECT_FALSE(day.off_at(13 * 60));
  const ScreenSchedule night = ScreenSchedule::parse("22:00-7:30");
  EXPECT_EQ(night.text(), "22:00-07:30");
  EXPECT_TRUE(night.off_at(23 * 60));
  EXPECT_TRUE(night.off_at(0));
  EXPECT_TRUE(night.off_at(7 * 60 + 29));
  EXPECT_FALSE(night.off_at(7 * 60 + 30));
  EXPECT_FALSE(night.off_at(21 * 60 + 59));
  EXPECT_TRUE(ScreenSchedule::parse("").empty());
  EXPECT_FALSE(ScreenSchedule::parse("").off_at(600));
}

TEST(ScreenSchedule, RefusesWhatIsNotAPeriod) {
  for (const char* bad : {"22:00", "24:00-07:00", "22:60-07:00", "22:00-22:00", "ten-eleven", "22:00-07:00x", "-1:00-07:00"}) {
    try {
      ScreenSchedule::parse(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << "the message names the text: " << e.what();
    }
  }
}
