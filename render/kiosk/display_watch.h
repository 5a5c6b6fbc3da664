#pragma once
// The kernel's word that displays changed: DRM uevents (a screen plugged or unplugged on a
// card: "change" with HOTPLUG=1; a card added or removed), read without blocking from the frame
// loop. The kernel's own uevents rather than udev's: the service runs in a private network
// namespace (PrivateNetwork=yes), where udevd's re-broadcast never arrives but the kernel's
// does, and a machine without udevd (the VM test's) has only those.
#include <memory>
#include <string>

struct udev;
struct udev_monitor;

namespace weft {

class DisplayWatch {
public:
  // Throws std::runtime_error saying why the events cannot be had (the caller polls instead).
  DisplayWatch();
  ~DisplayWatch();
  DisplayWatch(const DisplayWatch&) = delete;
  DisplayWatch& operator=(const DisplayWatch&) = delete;

  struct Events {
    bool changed = false;     // any DRM event: look at the connectors again
    bool card_added = false;  // a /dev/dri/card* appeared
    bool card_removed = false;
  };
  // The events since the last call, all of them read; never blocks.
  Events take();

private:
  udev* udev_ = nullptr;
  udev_monitor* monitor_ = nullptr;
};

}  // namespace weft
