#pragma once
// A HID transport that notes when the last report arrived (steady_clock nanoseconds since its
// epoch): the start of the kiosk's report→photon latency. Everything else goes to the wrapped
// transport unchanged.
#include <atomic>
#include <cstdint>
#include <memory>

#include "panel/hid_transport.h"

namespace weft {

class TimedHidTransport : public input::HidTransport {
public:
  TimedHidTransport(std::unique_ptr<input::HidTransport> inner, std::atomic<int64_t>* last_report_ns);
  std::unique_ptr<input::HidDevice> open(uint16_t vid, uint16_t pid, std::string& why) override;

private:
  std::unique_ptr<input::HidTransport> inner_;
  std::atomic<int64_t>* last_report_ns_;
};

}  // namespace weft
