#include "panel/simulated_panel.h"

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

#include "sim/panel_simulator.h"

namespace weft::input {
namespace {

using Clock = std::chrono::steady_clock;

class ReplayDevice final : public HidDevice {
public:
  ReplayDevice(const std::vector<sim::TimedReport>& reports, double speed)
      : reports_(reports), speed_(speed), start_(Clock::now()) {}
  int read(uint8_t* buffer, size_t capacity, int timeout_ms) override {
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    if (next_ >= reports_.size()) {
      std::this_thread::sleep_until(deadline);  // the hand has stopped: the panel is silent
      return 0;
    }
    const auto due = start_ + std::chrono::microseconds(static_cast<int64_t>(reports_[next_].time_us / speed_));
    if (due > deadline) {
      std::this_thread::sleep_until(deadline);
      return 0;
    }
    std::this_thread::sleep_until(due);
    const auto& bytes = reports_[next_++].bytes;
    const size_t n = std::min(capacity, bytes.size());
    std::copy(bytes.begin(), bytes.begin() + n, buffer);
    return static_cast<int>(n);
  }
  std::string last_error() const override { return "simulated panel"; }

private:
  const std::vector<sim::TimedReport>& reports_;
  double speed_;
  Clock::time_point start_;
  size_t next_ = 0;
};

class ReplayTransport final : public HidTransport {
public:
  ReplayTransport(std::vector<sim::TimedReport> reports, double speed) : reports_(std::move(reports)), speed_(speed) {}
  std::unique_ptr<HidDevice> open(uint16_t, uint16_t, std::string& why) override {
    if (opened_) {  // a replayed hand is played once; a reopen finds nothing
      why = "the simulated panel's script has been played";
      return nullptr;
    }
    opened_ = true;
    return std::make_unique<ReplayDevice>(reports_, speed_);
  }

private:
  std::vector<sim::TimedReport> reports_;
  double speed_;
  bool opened_ = false;
};

}  // namespace

SimulatedPanel make_simulated_panel(const std::string& script_text, double speed) {
  if (!(speed > 0)) throw PanelScriptError("simulated panel speed must be positive");
  try {
    auto reports = sim::simulate_script(script_text).reports;
    SimulatedPanel panel;
    panel.reports = reports.size();
    panel.seconds = reports.empty() ? 0.0 : reports.back().time_us / 1e6 / speed;
    panel.transport = std::make_unique<ReplayTransport>(std::move(reports), speed);
    return panel;
  } catch (const sim::ScriptError& e) {
    throw PanelScriptError(e.what());
  }
}

}  // namespace weft::input
