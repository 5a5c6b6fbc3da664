// Benchmark: time from a knob report arriving (hid_read returning its bytes on the HID thread)
// to the new parameters being visible to a render thread polling the AppearanceChannel.
// Runs the real HidKnobSource, KnobController and channel; only the USB device is replaced.
// Label `bench` (not in CI). Prints median / p99 / max over N reports.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

#include "firmware/hid_report.h"
#include "panel/hid_knob_source.h"
#include "panel/knob_controller.h"

using namespace weft::input;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int kReports = 20000;

struct Feed {
  std::atomic<int> released{0};  // reports the bench allows the device to deliver
  int delivered = 0;             // HID thread only
  std::vector<Clock::time_point> arrival = std::vector<Clock::time_point>(kReports);
};

class BenchDevice final : public HidDevice {
public:
  explicit BenchDevice(Feed& f) : f_(f) {}
  int read(uint8_t* buffer, size_t capacity, int timeout_ms) override {
    const auto end = Clock::now() + std::chrono::milliseconds(timeout_ms);
    while (f_.released.load(std::memory_order_acquire) <= f_.delivered) {
      if (Clock::now() > end) return 0;
    }
    weft::firmware::PanelReport r;
    r.sequence = static_cast<uint8_t>(f_.delivered);
    r.dial[0] = f_.delivered % 2 ? -1 : 1;  // hue back and forth: every report changes the state
    r.time_ms = static_cast<uint16_t>(f_.delivered * 200);
    const size_t n = weft::firmware::encode_report(r, buffer, capacity);
    f_.arrival[f_.delivered++] = Clock::now();
    return static_cast<int>(n);
  }
  std::string last_error() const override { return ""; }

private:
  Feed& f_;
};

class BenchTransport final : public HidTransport {
public:
  explicit BenchTransport(Feed& f) : f_(f) {}
  std::unique_ptr<HidDevice> open(uint16_t, uint16_t, std::string&) override {
    return std::make_unique<BenchDevice>(f_);
  }

private:
  Feed& f_;
};

}  // namespace

int main() {
  Feed feed;
  std::vector<PresetLook> presets(1);
  presets[0].name = "bench";
  presets[0].albedo = {{{0.06, 0.24, 0.30}, {0.06, 0.24, 0.30}}};
  KnobController controller(KnobMapper(presets), {}, [](const std::string&) {});
  controller.restore();
  HidSourceOptions options;
  HidKnobSource source(options, std::make_unique<BenchTransport>(feed), [](const std::string&) {});
  source.start(controller.sink());

  // This thread plays the render thread: it only ever polls version() and read().
  std::vector<double> latency_us(kReports);
  uint64_t seen = controller.channel().version();
  for (int i = 0; i < kReports; ++i) {
    feed.released.store(i + 1, std::memory_order_release);
    AppearanceState s;
    uint64_t v = seen;
    while ((v = controller.channel().version()) == seen) {
    }
    controller.channel().read(s);
    const auto visible = Clock::now();
    seen = v;
    latency_us[i] = std::chrono::duration<double, std::micro>(visible - feed.arrival[i]).count();
  }
  source.stop();
  std::sort(latency_us.begin(), latency_us.end());
  std::printf("panel report -> parameter visible to the render thread (%d reports)\n", kReports);
  std::printf("  median %.2f us   p99 %.2f us   p99.9 %.2f us   max %.2f us\n", latency_us[kReports / 2],
              latency_us[kReports * 99 / 100], latency_us[kReports * 999 / 1000], latency_us.back());
  std::printf("  (the max is the OS preempting one of the two spinning threads)\n");
  std::printf("  (a renderer polling once per frame adds up to one frame period on top)\n");
  return 0;
}
