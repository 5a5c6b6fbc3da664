#include "kiosk/service_notifier.h"

#include <systemd/sd-daemon.h>

namespace weft {

ServiceNotifier::ServiceNotifier() {
  uint64_t usec = 0;
  if (sd_watchdog_enabled(0, &usec) > 0) interval_ = std::chrono::microseconds(usec);
}

void ServiceNotifier::ready(const std::string& s) {
  sd_notify(0, ("READY=1\nSTATUS=" + s).c_str());
  if (watchdog_enabled()) {
    sd_notify(0, "WATCHDOG=1");
    last_ping_ = std::chrono::steady_clock::now();
  }
}

void ServiceNotifier::status(const std::string& s) { sd_notify(0, ("STATUS=" + s).c_str()); }

void ServiceNotifier::tick() {
  if (!watchdog_enabled()) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ping_ >= interval_ / 2) {
    sd_notify(0, "WATCHDOG=1");
    last_ping_ = now;
  }
}

void ServiceNotifier::stopping(const std::string& s) { sd_notify(0, ("STOPPING=1\nSTATUS=" + s).c_str()); }

}  // namespace weft
