#include "kiosk/knob_sources.h"

#include <algorithm>

#include "kiosk/kiosk_config_error.h"
#include "kiosk/timed_hid_transport.h"
#include "panel/gpio_knob_source.h"
#include "panel/hid_knob_source.h"
#include "panel/keyboard_knob_source.h"
#include "panel/simulated_panel.h"

namespace weft {
namespace {

std::unique_ptr<input::KnobSource> hid_source(std::unique_ptr<input::HidTransport> transport,
                                              const input::PanelConfig& panel, const KnobSourceOptions& options) {
  if (options.last_report_ns)
    transport = std::make_unique<TimedHidTransport>(std::move(transport), options.last_report_ns);
  return std::make_unique<input::HidKnobSource>(panel.hid, std::move(transport), options.log);
}

}  // namespace

KnobSources make_knob_sources(const std::vector<std::string>& names, const input::PanelConfig& panel,
                              const KnobSourceOptions& options) {
  KnobSources made;
  for (const std::string& name : names) {
    if (name.rfind("sim:", 0) == 0) {
      if (!(options.sim_speed > 0 && options.sim_speed <= 1000))
        throw KioskConfigError("--sim-speed: must be in (0, 1000]");
      input::SimulatedPanel sim;
      try {
        sim = input::make_simulated_panel(read_config_file(name.substr(4), options.script_flag), options.sim_speed);
      } catch (const input::PanelScriptError& e) {
        throw KioskConfigError(options.script_flag + ": " + e.what());
      }
      made.script_seconds = std::max(made.script_seconds, sim.seconds);
      made.sources.push_back(hid_source(std::move(sim.transport), panel, options));
    } else if (name == "hid") {
      made.sources.push_back(hid_source(input::make_hidapi_transport(), panel, options));
    } else if (name == "gpio") {
      made.sources.push_back(std::make_unique<input::GpioKnobSource>(panel.gpio, nullptr, options.log));
    } else if (name == "keyboard") {
      made.sources.push_back(std::make_unique<input::KeyboardKnobSource>(0, options.log));
    } else if (name != "none") {
      throw UnknownKnobSourceError(name);
    }
  }
  return made;
}

}  // namespace weft
