#pragma once
// The knob sources `weft run` and `weft panel` listen to, made from their names:
//   hid          the USB knob panel (hidapi), ids from the panel config
//   gpio         rotary encoders and buttons on GPIO lines (libgpiod), lines from the panel config
//   keyboard     the terminal's keys
//   sim:SCRIPT   a knob script played through the panel simulator and the real HID backend
//   none         no source (the knobs keep their saved state)
// Device trouble (absent, unplugged) is each source's to log and retry; only names and scripts
// are checked here.
#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "panel/knob_source.h"
#include "panel/panel_config.h"

namespace weft {

struct KnobSourceOptions {
  double sim_speed = 1.0;                  // sim: scripts play this many times faster, in (0, 1000]
  std::string script_flag = "--panel sim";
  // When set, HID sources (sim: included) store each report's arrival time here
  // (steady_clock ns): the start of the kiosk's report→photon latency.
  std::atomic<int64_t>* last_report_ns = nullptr;
  input::LogSink log;
};

class UnknownKnobSourceError : public std::runtime_error {
public:
  explicit UnknownKnobSourceError(const std::string& name)
      : std::runtime_error("unknown knob source '" + name + "'"), name_(name) {}
  const std::string& name() const { return name_; }

private:
  std::string name_;
};

struct KnobSources {
  std::vector<std::unique_ptr<input::KnobSource>> sources;
  double script_seconds = -1;  // when the longest sim: script's last report goes out; -1 without one
};

// One source per name, in order. Throws UnknownKnobSourceError for a name not listed above (the
// caller's flag decides the message), KioskConfigError for a bad speed or an unreadable or
// malformed script.
KnobSources make_knob_sources(const std::vector<std::string>& names, const input::PanelConfig& panel,
                              const KnobSourceOptions& options);

}  // namespace weft
