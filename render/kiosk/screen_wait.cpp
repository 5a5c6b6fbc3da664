#include "kiosk/screen_wait.h"

namespace weft {

ScreenWait::ScreenWait(double wait_s, Clock::time_point start, std::time_t start_utc)
    : wait_(wait_s), since_(start), since_utc_(start_utc) {}

ScreenWait::Report ScreenWait::update(bool has_screen, Clock::time_point now, std::time_t now_utc) {
  if (has_screen) {
    has_screen_ = true;
    if (!reported_) return Report::none;
    reported_ = false;
    return Report::back;
  }
  if (has_screen_) {  // it went away just now: a new stretch without one
    has_screen_ = false;
    since_ = now;
    since_utc_ = now_utc;
  }
  if (reported_ || wait_.count() <= 0 || now - since_ < wait_) return Report::none;
  reported_ = true;
  return Report::missing;
}

double ScreenWait::seconds_without(Clock::time_point now) const {
  return has_screen_ ? 0.0 : std::chrono::duration<double>(now - since_).count();
}

}  // namespace weft
