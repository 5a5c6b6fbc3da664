#pragma once
// Stand-ins for the panel's byte and edge sources, so the HID and GPIO backends run in tests
// exactly as on a kiosk but fed by the simulator (or by garbage and failures on purpose).
#include <atomic>
#include <chrono>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/fabric.h"
#include "panel/gpio_lines.h"
#include "panel/hid_transport.h"
#include "panel/knob_mapping.h"
#include "sim/line_waveform.h"

namespace weft::test {

// What the fake panel does on each read: deliver bytes, fail (unplug), or time out.
struct HidStep {
  enum Kind { bytes, error, timeout } kind = bytes;
  std::vector<uint8_t> data;
};

struct FakeHidScript {
  std::mutex m;
  std::deque<HidStep> steps;
  std::deque<bool> open_results;  // consumed per open(); empty → succeed
  std::atomic<int> opens{0}, failed_opens{0};
  std::atomic<bool> drained{false};  // a read found nothing left after all steps
};

class FakeHidDevice final : public input::HidDevice {
public:
  explicit FakeHidDevice(FakeHidScript& s) : s_(s) {}
  int read(uint8_t* buffer, size_t capacity, int) override {
    HidStep step;
    {
      std::lock_guard lock(s_.m);
      if (s_.steps.empty()) {
        s_.drained = true;
        step.kind = HidStep::timeout;
      } else {
        step = std::move(s_.steps.front());
        s_.steps.pop_front();
      }
    }
    if (step.kind == HidStep::timeout) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      return 0;
    }
    if (step.kind == HidStep::error) return -1;
    const size_t n = std::min(capacity, step.data.size());
    std::copy(step.data.begin(), step.data.begin() + n, buffer);
    return static_cast<int>(n);
  }
  std::string last_error() const override { return "No such device (fake unplug)"; }

private:
  FakeHidScript& s_;
};

class FakeHidTransport final : public input::HidTransport {
public:
  explicit FakeHidTransport(FakeHidScript& s) : s_(s) {}
  std::unique_ptr<input::HidDevice> open(uint16_t, uint16_t, std::string& why) override {
    bool ok = true;
    {
      std::lock_guard lock(s_.m);
      if (!s_.open_results.empty()) {
        ok = s_.open_results.front();
        s_.open_results.pop_front();
      }
    }
    if (!ok) {
      ++s_.failed_opens;
      why = "no device matches (fake)";
      return nullptr;
    }
    ++s_.opens;
    return std::make_unique<FakeHidDevice>(s_);
  }

private:
  FakeHidScript& s_;
};

// Simulator edges on a virtual clock: sim line i is GPIO offset i (see gpio_config_for_sim).
class FakeGpioLines final : public input::GpioLines {
public:
  explicit FakeGpioLines(std::vector<sim::LineEdge> edges, std::atomic<bool>& drained)
      : edges_(std::move(edges)), drained_(drained) {}
  std::vector<std::pair<unsigned, int>> levels() override {
    std::vector<std::pair<unsigned, int>> out;
    for (unsigned i = 0; i < static_cast<unsigned>(sim::kLineCount); ++i) out.emplace_back(i, 1);
    return out;
  }
  Wait wait(int timeout_ms, std::vector<input::GpioEdge>& out) override {
    const uint64_t horizon = now_ns_ + static_cast<uint64_t>(timeout_ms) * 1000000ull;
    if (next_ < edges_.size() && edges_[next_].time_us * 1000ull <= horizon) {
      now_ns_ = edges_[next_].time_us * 1000ull;
      for (; next_ < edges_.size() && edges_[next_].time_us * 1000ull == now_ns_; ++next_)
        out.push_back({edges_[next_].line, edges_[next_].level, now_ns_});
      return Wait::edges;
    }
    now_ns_ = horizon;
    if (next_ == edges_.size()) {
      drained_ = true;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return Wait::timeout;
  }
  uint64_t now_ns() override { return now_ns_; }
  std::string last_error() const override { return "fake"; }

private:
  std::vector<sim::LineEdge> edges_;
  size_t next_ = 0;
  uint64_t now_ns_ = 0;
  std::atomic<bool>& drained_;
};

inline input::GpioPanelConfig gpio_config_for_sim() {
  input::GpioPanelConfig c;
  c.chip = "fake";
  for (int d = 0; d < input::kDialCount; ++d) c.encoder_a[d] = 2 * d, c.encoder_b[d] = 2 * d + 1;
  for (int b = 0; b < input::kButtonCount; ++b) c.buttons[b] = sim::kFirstButtonLine + b;
  return c;
}

// The fabric presets as the renderer would hand them to the mapper.
inline std::vector<input::PresetLook> installed_presets() {
  std::vector<input::PresetLook> out;
  for (const auto& name : list_fabric_presets(std::string(WEFT_SOURCE_ASSETS) + "/fabrics")) {
    const Fabric f = load_fabric_preset(name, std::string(WEFT_SOURCE_ASSETS) + "/fabrics");
    input::PresetLook look;
    look.name = f.name;
    for (int t = 0; t < 2; ++t)
      for (int k = 0; k < 3; ++k) look.albedo[t][k] = f.threads[t].albedo[k];
    out.push_back(look);
  }
  return out;
}

inline uint32_t preset_index(const std::vector<input::PresetLook>& presets, const std::string& name) {
  for (size_t i = 0; i < presets.size(); ++i)
    if (presets[i].name == name) return static_cast<uint32_t>(i);
  throw std::runtime_error("preset " + name + " not installed");
}

// Collects log lines for assertions.
struct LogCapture {
  std::mutex m;
  std::vector<std::string> lines;
  input::LogSink sink() {
    return [this](weft::LogPriority, const std::string& l) {
      std::lock_guard lock(m);
      lines.push_back(l);
    };
  }
  bool contains(const std::string& needle) {
    std::lock_guard lock(m);
    for (const auto& l : lines)
      if (l.find(needle) != std::string::npos) return true;
    return false;
  }
  std::string all() {
    std::lock_guard lock(m);
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
  }
};

template <class Pred>
bool wait_until(Pred pred, std::chrono::milliseconds limit = std::chrono::seconds(10)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!pred()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

}  // namespace weft::test
