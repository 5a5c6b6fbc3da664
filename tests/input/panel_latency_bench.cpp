// Benchmark: time from a knob report arriving (hid_read returning its bytes on the HID thread)
// to the new parameters being visible to a render thread polling the AppearanceChannel.
// Runs the real HidKnobSource, KnobController and channel; only the USB device is replaced.
// Label `bench` (not in CI). Prints median / p99 / max over N reports. The arrival time is
// taken when the read returns the bytes (after the reader thread woke up), as hid_read would.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
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
  std::mutex m;
  std::condition_variable cv;
  int released = 0;              // reports the bench allows the device to deliver (under m)
  int delivered = 0;             // HID thread only
  std::vector<Clock::time_point> arrival = std::vector<Clock::time_point>(kReports);
};

class BenchDevice final : public HidDevice {
public:
  explicit BenchDevice(Feed& f) : f_(f) {}
  int read(uint8_t* buffer, size_t capacity, int timeout_ms) override {
    {
      // Blocks like hid_read_timeout in poll(): the reader sleeps until the "USB" delivers.
      std::unique_lock lock(f_.m);
      if (!f_.cv.wait_for(lock, std::chrono::milliseconds(timeout_ms), [&] { return f_.released > f_.delivered; }))
        return 0;
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
  KnobController controller(KnobMapper(presets), {}, [](weft::LogPriority, const std::string&) {});
  controller.restore();
  HidSourceOptions options;
  HidKnobSource source(options, std::make_unique<BenchTransport>(feed), [](weft::LogPriority, const std::string&) {});
  source.start(controller.sink());

  // This thread plays the render thread: it only ever polls version() and read().
  std::vector<double> latency_us(kReports);
  uint64_t seen = controller.channel().version();
  for (int i = 0; i < kReports; ++i) {
    {
      std::lock_guard lock(feed.m);
      feed.released = i + 1;
    }
    feed.cv.notify_one();
    AppearanceState s;
    uint64_t v = seen;
    while ((v = controller.channel().version()) == seen) std::this_thread::yield();
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
  std::printf("  (tail outliers are the OS preempting a thread on a busy machine)\n");
  std::printf("  (a renderer polling once per frame adds up to one frame period on top)\n");
  return 0;
}
