// The kiosk's screen coming and going: Kiosk's members that follow the display's hotplug
// (kiosk/kiosk_display.h) and report a kiosk left without a screen (kiosk/screen_wait.h).
//
// Without a screen the frame loop runs on (frames drawn offscreen, knobs and content updates
// followed) and keeps pinging the watchdog: the process is healthy, and a restart would bring no
// screen, only restart loops that hide the cause. What is missing is said instead, in the
// journal (warning), the service's STATUS and the status file's "display".
#include <cstdio>
#include <ctime>

#include "gl/offscreen_target.h"
#include "kiosk/camera_zoom.h"
#include "kiosk/kiosk.h"
#include "kiosk/kiosk_log.h"
#include "kiosk/kiosk_renderer.h"
#include "kiosk/kiosk_status.h"

namespace weft {

DisplaySettings Kiosk::display_settings() const {
  DisplaySettings s;
  s.display = config_.display;
  s.width = config_.size[0];
  s.height = config_.size[1];
  s.connector = config_.connector;
  s.mode = config_.mode;
  s.rotation = config_.rotation;
  return s;
}

void Kiosk::follow_display(Clock::time_point now) {
  switch (display_->poll(now)) {
    case KioskDisplay::Change::none:
      break;
    case KioskDisplay::Change::shown: {
      char line[160];
      std::snprintf(line, sizeof line, " after %.1f s without a screen", screen_wait_->seconds_without(now));
      kiosk_log_info("showing '" + scene_->scene.name + "' on " + display_->description() + line);
      if (display_->width() != width_ || display_->height() != height_)
        resize_frame();  // drawn and presented at the new size
      else
        present(now);  // the frame drawn last, at once
      notifier_.status("showing '" + scene_->scene.name + "' on " + display_->description());
      break;
    }
    case KioskDisplay::Change::lost:
      kiosk_log_warning("no screen: '" + scene_->scene.name + "' is drawn offscreen until one is connected (" +
                        display_->connectors() + ")");
      notifier_.status("no screen (unplugged); waiting for one on " + display_->connectors());
      break;
    case KioskDisplay::Change::card_appeared:
      kiosk_log_warning("a display card appeared: stopping for the service to start the kiosk again on it");
      restart_ = true;
      break;
    case KioskDisplay::Change::card_gone:
      kiosk_log_error("the display card is gone (unplugged, or its driver unloaded): stopping for the service to start the "
                      "kiosk again on the display there is now");
      restart_ = true;
      break;
  }
  report_screen(now);
}

void Kiosk::resize_frame() {
  width_ = display_->width();
  height_ = display_->height();
  target_ = std::make_unique<gpu::OffscreenTarget>(width_, height_);
  closeup_ = closeup_of(scene_->scene, cloth_fabrics_, height_);
  arm_weave_range(*renderer_, *scene_, closeup_, width_, height_);
  renderer_->refresh_all();
  draw_frame(shown_turn_);
  ++drawn_;
}

void Kiosk::report_screen(Clock::time_point now) {
  if (!display_->follows_screens()) return;
  switch (screen_wait_->update(display_->has_screen(), now, std::time(nullptr))) {
    case ScreenWait::Report::none:
      break;
    case ScreenWait::Report::missing: {
      char line[96];
      std::snprintf(line, sizeof line, "NO DISPLAY: no screen for %.0f s (since ", screen_wait_->seconds_without(now));
      const std::string since = utc(screen_wait_->none_since());
      kiosk_log_warning(line + since + "); the kiosk runs but nothing is shown. Connectors: " + display_->connectors() +
                        ". Check the screen's power and cable" +
                        (config_.connector.empty() ? "" : ", and that it is on " + config_.connector));
      notifier_.status("NO DISPLAY since " + since + ": nothing shown (" + display_->connectors() + ")");
      write_status("running");
      break;
    }
    case ScreenWait::Report::back:
      kiosk_log_info("display back: " + display_->description());
      break;
  }
}

std::string Kiosk::display_status() const {
  if (display_->has_screen() || !display_->follows_screens() || !screen_wait_) return display_->name();
  return "none since " + utc(screen_wait_->none_since());
}

}  // namespace weft
