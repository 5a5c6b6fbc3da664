#pragma once
// How long the kiosk may be without a screen before it says so: from boot, or from the moment a
// screen went away, for --display-wait seconds. Past that, one report (journal warning, service
// STATUS, the status file), and one more when a screen is back. Decisions only: the kiosk does
// the telling (kiosk_screen.cpp).
#include <chrono>
#include <ctime>

namespace weft {

class ScreenWait {
public:
  using Clock = std::chrono::steady_clock;

  // wait_s: seconds without a screen before the report; 0: never report. `start`: boot.
  ScreenWait(double wait_s, Clock::time_point start, std::time_t start_utc);

  enum class Report {
    none,
    missing,  // no screen for wait_s: say so
    back,     // a screen again after a `missing` report
  };
  // Each tick: whether a screen is shown now. `now_utc` stamps the start of a stretch without one.
  Report update(bool has_screen, Clock::time_point now, std::time_t now_utc);

  bool missing() const { return reported_; }   // reported missing and not back since
  std::time_t none_since() const { return since_utc_; }  // valid while there is no screen
  double seconds_without(Clock::time_point now) const;   // 0 while a screen is shown

private:
  std::chrono::duration<double> wait_;
  bool has_screen_ = false;
  bool reported_ = false;
  Clock::time_point since_;
  std::time_t since_utc_;
};

}  // namespace weft
