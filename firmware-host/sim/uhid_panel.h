#pragma once
// The simulated panel as a real HID device: creates it through the kernel's uhid interface
// (/dev/uhid) with the panel's own report descriptor and USB IDs, so a host finds it through
// hidraw exactly like the USB panel, then feeds it the input reports the firmware sends.
// Closing (or destroy()) unplugs it.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace weft::sim {

class UhidError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct UhidIdentity {
  uint16_t vendor_id = 0;
  uint16_t product_id = 0;
  std::string name = "Weft knob panel (simulated)";
};

class UhidPanel {
public:
  // Opens the uhid character device (normally /dev/uhid) and creates the panel on it.
  static UhidPanel open(const std::string& uhid_path, const UhidIdentity& id);
  // Creates the panel on an already open uhid file descriptor (tests pass a socket pair end);
  // takes ownership of `fd`. Throws UhidError when the kernel refuses the device.
  UhidPanel(int fd, const UhidIdentity& id);
  UhidPanel(UhidPanel&& other) noexcept;
  UhidPanel& operator=(UhidPanel&&) = delete;
  ~UhidPanel();  // destroys the device (an unplug)

  // Handles the kernel's events until a host has the device open (UHID_OPEN: some reader has
  // /dev/hidrawN open); false after `timeout_ms` without one.
  bool wait_until_opened(int timeout_ms);
  bool opened() const { return open_count_ > 0; }
  // Sends one input report (report ID first, as on the wire). Handles pending events first.
  void send_report(const uint8_t* bytes, size_t size);
  // Unplugs the device now (UHID_DESTROY); later calls do nothing.
  void destroy();

private:
  void handle_events(int timeout_ms);
  void write_event(const void* event, size_t size, const char* what);
  int fd_ = -1;
  int open_count_ = 0;
  bool started_ = false;
};

}  // namespace weft::sim
