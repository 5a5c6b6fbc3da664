#pragma once
// The kiosk's side of systemd's notify protocol (sd_notify): READY=1 once the first frame is
// shown, STATUS= lines an operator reads in `systemctl status`, and WATCHDOG=1 pings from the
// frame loop at half the WatchdogSec interval, so a loop that stops presenting gets restarted.
// Without NOTIFY_SOCKET (run by hand) every call is a no-op.
#include <chrono>
#include <string>

namespace weft {

class ServiceNotifier {
public:
  ServiceNotifier();
  bool watchdog_enabled() const { return interval_.count() > 0; }
  std::chrono::microseconds watchdog_interval() const { return interval_; }
  void ready(const std::string& status);
  void status(const std::string& status);
  // Call from the frame loop each tick: pings when half the watchdog interval has passed.
  void tick();
  void stopping(const std::string& status);

private:
  std::chrono::microseconds interval_{0};  // WATCHDOG_USEC, 0 when not enabled
  std::chrono::steady_clock::time_point last_ping_{};
};

}  // namespace weft
