#include "kiosk/idle_return.h"

#include <algorithm>

#include "panel/appearance_blend.h"

namespace weft {

IdleReturn::IdleReturn(double idle_seconds, double ease_seconds)
    : idle_seconds_(idle_seconds), ease_seconds_(std::max(ease_seconds, 0.0)) {}

void IdleReturn::touched(Clock::time_point now) {
  last_touch_ = now;
  home_ = false;
  easing_ = false;
}

bool IdleReturn::due(Clock::time_point now) const {
  return idle_seconds_ > 0.0 && !home_ && !easing_ && std::chrono::duration<double>(now - last_touch_).count() >= idle_seconds_;
}

void IdleReturn::start(const input::AppearanceState& from, const input::AppearanceState& home, Clock::time_point now) {
  from_ = from;
  home_state_ = home;
  ease_start_ = now;
  easing_ = from != home;  // already home: nothing to redraw
  home_ = true;
}

std::optional<input::AppearanceState> IdleReturn::step(Clock::time_point now) {
  if (!easing_) return std::nullopt;
  const double t = ease_seconds_ > 0.0 ? std::chrono::duration<double>(now - ease_start_).count() / ease_seconds_ : 1.0;
  if (t >= 1.0) easing_ = false;
  // Smoothstep: the look leaves and arrives gently.
  const double s = std::clamp(t, 0.0, 1.0);
  return input::blend_appearance(from_, home_state_, t >= 1.0 ? 1.0 : s * s * (3.0 - 2.0 * s));
}

}  // namespace weft
