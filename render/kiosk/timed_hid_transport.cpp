#include "kiosk/timed_hid_transport.h"

#include <chrono>

namespace weft {
namespace {

class TimedHidDevice : public input::HidDevice {
public:
  TimedHidDevice(std::unique_ptr<input::HidDevice> inner, std::atomic<int64_t>* last_report_ns)
      : inner_(std::move(inner)), last_report_ns_(last_report_ns) {}
  int read(uint8_t* buffer, size_t size, int timeout_ms) override {
    const int r = inner_->read(buffer, size, timeout_ms);
    if (r > 0) last_report_ns_->store(std::chrono::steady_clock::now().time_since_epoch().count());
    return r;
  }
  std::string last_error() const override { return inner_->last_error(); }

private:
  std::unique_ptr<input::HidDevice> inner_;
  std::atomic<int64_t>* last_report_ns_;
};

}  // namespace

TimedHidTransport::TimedHidTransport(std::unique_ptr<input::HidTransport> inner, std::atomic<int64_t>* last_report_ns)
    : inner_(std::move(inner)), last_report_ns_(last_report_ns) {}

std::unique_ptr<input::HidDevice> TimedHidTransport::open(uint16_t vid, uint16_t pid, std::string& why) {
  auto device = inner_->open(vid, pid, why);
  if (!device) return nullptr;
  return std::make_unique<TimedHidDevice>(std::move(device), last_report_ns_);
}

}  // namespace weft
