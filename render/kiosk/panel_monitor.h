#pragma once
// `weft panel`: the kiosk's knob sources run alone, printing what the renderer would get as one
// JSON line per change (the fabric with the knobs applied). For commissioning a kiosk's panel,
// and for trying the knobs without one (a knob script through the simulated USB panel).
#include <atomic>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace weft {

struct PanelMonitorConfig {
  std::string panel_config;          // JSON: sources, hid ids, gpio lines, state_file; empty: defaults, no state
  std::vector<std::string> sources;  // knob sources (kiosk/knob_sources.h); empty: the panel config's
  std::string simulate;              // a knob script played through a simulated USB panel, instead of the sources
  double speed = 1.0;                // the script plays this many times faster
  std::string state;                 // knob state file (overrides the panel config's)
  bool no_state = false;             // neither restore nor save knob state
  std::string fabric = "linen_plain";  // the preset to start from when no state is saved
  double duration = -1;              // seconds to run; < 0: until stop (with a script: its length)
  std::filesystem::path fabrics_dir; // where the fabric presets are
};

// Runs until `stop`, or for the duration; returns 0. Throws KioskConfigError for bad
// configuration, FabricError for an unknown fabric.
int run_panel_monitor(const PanelMonitorConfig& config, const std::atomic<bool>& stop, std::ostream& out);

}  // namespace weft
