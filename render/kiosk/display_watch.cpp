#include "kiosk/display_watch.h"

#include <libudev.h>

#include <cstring>
#include <stdexcept>

namespace weft {

DisplayWatch::DisplayWatch() {
  udev_ = udev_new();
  if (!udev_) throw std::runtime_error("udev_new failed");
  monitor_ = udev_monitor_new_from_netlink(udev_, "kernel");
  if (!monitor_ || udev_monitor_filter_add_match_subsystem_devtype(monitor_, "drm", nullptr) < 0 ||
      udev_monitor_enable_receiving(monitor_) < 0) {
    if (monitor_) udev_monitor_unref(monitor_);
    udev_unref(udev_);
    throw std::runtime_error(std::string("cannot listen to the kernel's DRM events: ") + std::strerror(errno));
  }
}

DisplayWatch::~DisplayWatch() {
  udev_monitor_unref(monitor_);
  udev_unref(udev_);
}

DisplayWatch::Events DisplayWatch::take() {
  Events e;
  // The monitor's socket is non-blocking: receive returns null once it is drained.
  while (udev_device* d = udev_monitor_receive_device(monitor_)) {
    e.changed = true;
    const char* action = udev_device_get_action(d);
    const char* name = udev_device_get_sysname(d);
    // "card0" itself, not its connectors ("card0-HDMI-A-1") or render node.
    const bool card = name && std::strncmp(name, "card", 4) == 0 && !std::strchr(name, '-');
    if (card && action && std::strcmp(action, "add") == 0) e.card_added = true;
    if (card && action && std::strcmp(action, "remove") == 0) e.card_removed = true;
    udev_device_unref(d);
  }
  return e;
}

}  // namespace weft
