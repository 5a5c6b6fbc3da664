// `weft panel`: runs the knob sources alone and prints what the renderer would get, one JSON line
// per change. For commissioning a kiosk's panel, and for trying the knobs without one
// (`--simulate SCRIPT` plays a knob script through the panel simulator and the real HID backend).
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/knob_appearance.h"
#include "panel/gpio_knob_source.h"
#include "panel/hid_knob_source.h"
#include "panel/keyboard_knob_source.h"
#include "panel/knob_controller.h"
#include "panel/panel_config.h"
#include "panel/simulated_panel.h"

namespace weft {
namespace {

std::atomic<bool> g_interrupted{false};

struct PanelArgs {
  std::string config;
  std::vector<std::string> sources;
  std::string simulate;
  double speed = 1.0;
  std::string state;
  bool no_state = false;
  std::string fabric = "linen_plain";
  double duration = -1;
};

// Six significant digits: the knobs' floats, printed without float→double noise.
double tidy(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", x);
  return std::strtod(s, nullptr);
}

nlohmann::ordered_json describe(const Fabric& f, const input::AppearanceState& s) {
  static const char* kSelection[] = {"both", "warp", "weft"};
  nlohmann::ordered_json j;
  j["fabric"] = f.name;
  j["editing"] = kSelection[static_cast<int>(s.selection) % 3];
  j["env_rotation_deg"] = tidy(s.env_rotation_deg);
  for (int t = 0; t < 2; ++t) {
    const ThreadParams& p = f.threads[t];
    j[t == 0 ? "warp" : "weft"] = {{"A", {tidy(p.albedo.r), tidy(p.albedo.g), tidy(p.albedo.b)}},
                                   {"gamma_s_deg", tidy(glm::degrees(p.gamma_s))},
                                   {"gamma_v_deg", tidy(glm::degrees(p.gamma_v))}};
  }
  return j;
}

int run_panel(const PanelArgs& a) {
  input::PanelConfig config;
  if (!a.config.empty()) {
    try {
      config = input::parse_panel_config(read_argument_file(a.config, "--config"), a.config);
    } catch (const input::PanelConfigError& e) {
      throw UsageError(e.what());
    }
  } else {
    config.state_file.clear();  // a bare `weft panel` persists nothing unless asked
  }
  if (!a.sources.empty()) config.sources = a.sources;
  if (!a.state.empty()) config.state_file = a.state;
  if (a.no_state) config.state_file.clear();
  if (!(a.speed > 0 && a.speed <= 1000)) throw UsageError("--speed: must be in (0, 1000]");

  const auto dir = assets_dir() / "fabrics";
  std::vector<Fabric> presets;
  for (const auto& name : list_fabric_presets(dir)) presets.push_back(load_fabric_preset(name, dir));
  if (presets.empty()) throw UsageError("no fabric presets in " + dir.string());
  uint32_t default_preset = presets.size();
  for (size_t i = 0; i < presets.size(); ++i)
    if (presets[i].name == a.fabric) default_preset = static_cast<uint32_t>(i);
  if (default_preset == presets.size()) load_fabric_preset(a.fabric, dir);  // throws naming the known ones

  const auto log = input::stderr_log();
  input::KnobControllerOptions options;
  options.state_file = config.state_file;
  options.default_preset = default_preset;
  input::KnobController controller(input::KnobMapper(preset_looks(presets)), options, log);
  controller.restore();

  std::vector<std::unique_ptr<input::KnobSource>> sources;
  double duration = a.duration;
  if (!a.simulate.empty()) {
    input::SimulatedPanel panel;
    try {
      panel = input::make_simulated_panel(read_argument_file(a.simulate, "--simulate"), a.speed);
    } catch (const input::PanelScriptError& e) {
      throw UsageError(std::string("--simulate: ") + e.what());
    }
    if (duration < 0) duration = panel.seconds + 0.3;
    sources.push_back(std::make_unique<input::HidKnobSource>(config.hid, std::move(panel.transport), log));
  } else {
    for (const auto& s : config.sources) {
      if (s == "hid") sources.push_back(std::make_unique<input::HidKnobSource>(config.hid, input::make_hidapi_transport(), log));
      else if (s == "gpio") sources.push_back(std::make_unique<input::GpioKnobSource>(config.gpio, nullptr, log));
      else if (s == "keyboard") sources.push_back(std::make_unique<input::KeyboardKnobSource>(0, log));
      else throw UsageError("--source: unknown source '" + s + "' (hid, gpio or keyboard)");
    }
  }
  for (auto& s : sources) {
    log("listening to " + s->describe());
    s->start(controller.sink());
  }

  std::signal(SIGINT, [](int) { g_interrupted = true; });
  std::signal(SIGTERM, [](int) { g_interrupted = true; });
  // Stand-in for the frame loop: poll the channel once per 60 Hz frame, never block on it.
  const auto start = std::chrono::steady_clock::now();
  uint64_t seen = ~0ull;
  while (!g_interrupted) {
    if (duration >= 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > duration) break;
    if (controller.channel().version() != seen) {
      input::AppearanceState s;
      uint64_t v = 0;
      if (controller.channel().read(s, &v)) {
        seen = v;
        const Fabric f = apply_knobs(presets.at(s.preset_index), s);
        std::cout << describe(f, s).dump() << std::endl;
      }
    }
    std::this_thread::sleep_for(std::chrono::microseconds(16667));
  }
  for (auto& s : sources) s->stop();
  controller.flush();
  return 0;
}

}  // namespace

CommandAction add_panel_command(CLI::App& app) {
  auto a = std::make_shared<PanelArgs>();
  CLI::App* sub = app.add_subcommand(
      "panel", "Run the knob panel alone: prints the fabric parameters the renderer would get, one JSON line per change");
  sub->add_option("--config", a->config, "Panel configuration (JSON: sources, hid ids, gpio lines, state_file)");
  sub->add_option("--source", a->sources, "Knob source: hid, gpio or keyboard (repeatable; overrides the config)");
  sub->add_option("--simulate", a->simulate, "Play a knob script (weft-panel-sim format) through a simulated USB panel");
  sub->add_option("--speed", a->speed, "Play the --simulate script this many times faster")->capture_default_str();
  sub->add_option("--state", a->state, "Knob state file to restore and save (overrides the config)");
  sub->add_flag("--no-state", a->no_state, "Neither restore nor save knob state");
  sub->add_option("--fabric", a->fabric, "Fabric preset to start from when no state is saved")->capture_default_str();
  sub->add_option("--duration", a->duration, "Seconds to run (default: until Ctrl-C; with --simulate, the script's length)");
  return [a] { return run_panel(*a); };
}

}  // namespace weft
