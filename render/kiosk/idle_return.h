#pragma once
// The knobs' way home: after a while with nobody at the panel, the kiosk eases the look back to
// where the bundle starts it (the fabric a shopper walking up should see first), then keeps it.
// Each step of the way is a look (panel/appearance_blend.h) that the kiosk applies as it applies
// the knobs' (kiosk/look_applier.h).
#include <chrono>
#include <optional>

#include "panel/appearance_state.h"

namespace weft {

class IdleReturn {
public:
  using Clock = std::chrono::steady_clock;
  // idle_seconds ≤ 0: never (the look stays as the knobs left it); ease_seconds: the way home.
  IdleReturn(double idle_seconds, double ease_seconds);

  void touched(Clock::time_point now);  // a knob changed (a person, or boot)
  // True when the knobs have been idle for idle_seconds and the look is not already on its way or
  // home: the caller puts the knobs home (KioskKnobs::go_home) and calls start.
  bool due(Clock::time_point now) const;
  void start(const input::AppearanceState& from, const input::AppearanceState& home, Clock::time_point now);
  // During the ease: the look to show at `now` (the last one is `home` itself); empty otherwise.
  std::optional<input::AppearanceState> step(Clock::time_point now);
  bool easing() const { return easing_; }

private:
  double idle_seconds_, ease_seconds_;
  Clock::time_point last_touch_{};
  bool home_ = true;  // nothing to return from until a knob moves
  bool easing_ = false;
  Clock::time_point ease_start_{};
  input::AppearanceState from_{}, home_state_{};
};

}  // namespace weft
