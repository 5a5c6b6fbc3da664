// The kiosk while nobody is at it: the knobs' way home after --idle-return (kiosk/idle_return.h)
// and the screen's sleep during --screen-off (kiosk/screen_schedule.h). Kiosk's own members, kept
// here so kiosk.cpp reads as its steps.
#include "kiosk/kiosk.h"
#include "kiosk/kiosk_knobs.h"

namespace weft {

bool Kiosk::return_when_idle(Clock::time_point now) {
  if (idle_.due(now)) {
    const input::AppearanceState from = knobs_->state();
    knobs_->go_home(*scene_, config_.idle_return_s);
    knobs_->poll();  // the look at home: eased into below, not shown at once
    idle_.start(from, knobs_->state(), now);
  }
  const std::optional<input::AppearanceState> look = idle_.step(now);
  if (!look) return false;
  look_applier_.apply(*look);
  return true;
}

bool Kiosk::screen_asleep(Clock::time_point now) {
  if (screen_schedule_.empty()) return false;
  // The wall clock once a second is plenty for a schedule in minutes.
  if (screen_checked_ && now - screen_checked_at_ < std::chrono::seconds(1)) return screen_off_;
  screen_checked_ = true;
  screen_checked_at_ = now;
  const bool off = screen_schedule_.off_at(local_minute_of_day());
  if (off == screen_off_) return off;
  screen_off_ = off;
  display_->set_power(!off);
  notifier_.status(off ? "screen off until the end of " + screen_schedule_.text() + " (--screen-off)"
                       : "showing '" + scene_->scene.name + "' on " + display_->description());
  write_status("running");
  return off;
}

}  // namespace weft
