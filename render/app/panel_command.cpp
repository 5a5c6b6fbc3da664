// `weft panel`: the knob sources alone, one JSON line per change (render/kiosk/panel_monitor.h).
// This file turns the flags into a PanelMonitorConfig and runs it until Ctrl-C or the duration.
#include <atomic>
#include <csignal>
#include <iostream>

#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/commands.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/panel_monitor.h"

namespace weft {
namespace {

std::atomic<bool> g_interrupted{false};

int run_panel(PanelMonitorConfig config) {
  std::signal(SIGINT, [](int) { g_interrupted = true; });
  std::signal(SIGTERM, [](int) { g_interrupted = true; });
  config.fabrics_dir = assets_dir() / "fabrics";
  try {
    return run_panel_monitor(config, g_interrupted, std::cout);
  } catch (const KioskConfigError& e) {
    throw UsageError(e.what());
  }
}

}  // namespace

CommandAction add_panel_command(CLI::App& app) {
  auto a = std::make_shared<PanelMonitorConfig>();
  CLI::App* sub = app.add_subcommand(
      "panel", "Run the knob panel alone: prints the fabric parameters the renderer would get, one JSON line per change");
  sub->add_option("--panel-config,--config", a->panel_config, "Panel configuration (JSON: sources, hid ids, gpio lines, state_file)");
  sub->add_option("--source", a->sources,
                  "Knob source: hid, gpio, keyboard, sim:SCRIPT or none (repeatable; overrides the config)");
  sub->add_option("--simulate", a->simulate, "Play a knob script (weft-panel-sim format) through a simulated USB panel");
  sub->add_option("--sim-speed,--speed", a->speed, "Play the --simulate script this many times faster")
      ->check(CLI::PositiveNumber & CLI::Range(0.0, 1000.0))->capture_default_str();
  sub->add_option("--state", a->state, "Knob state file to restore and save (overrides the config)");
  sub->add_flag("--no-state", a->no_state, "Neither restore nor save knob state");
  sub->add_option("--fabric", a->fabric, "Fabric preset to start from when no state is saved")->capture_default_str();
  sub->add_option("--duration", a->duration, "Seconds to run (default: until Ctrl-C; with --simulate, the script's length)");
  return [a] { return run_panel(*a); };
}

}  // namespace weft
