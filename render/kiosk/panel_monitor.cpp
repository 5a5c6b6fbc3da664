#include "kiosk/panel_monitor.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <thread>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/fabric.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/knob_appearance.h"
#include "kiosk/knob_sources.h"
#include "panel/knob_controller.h"
#include "panel/panel_config.h"

namespace weft {
namespace {

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

input::PanelConfig read_panel_config(const PanelMonitorConfig& c) {
  input::PanelConfig config;
  if (!c.panel_config.empty()) {
    try {
      config = input::parse_panel_config(read_config_file(c.panel_config, "--panel-config"), c.panel_config);
    } catch (const input::PanelConfigError& e) {
      throw KioskConfigError(e.what());
    }
  } else {
    config.state_file.clear();  // a bare `weft panel` persists nothing unless asked
  }
  if (!c.sources.empty()) config.sources = c.sources;
  if (!c.state.empty()) config.state_file = c.state;
  if (c.no_state) config.state_file.clear();
  return config;
}

}  // namespace

int run_panel_monitor(const PanelMonitorConfig& c, const std::atomic<bool>& stop, std::ostream& out) {
  const input::PanelConfig config = read_panel_config(c);
  if (!(c.speed > 0 && c.speed <= 1000)) throw KioskConfigError("--sim-speed: must be in (0, 1000]");

  std::vector<Fabric> presets;
  for (const auto& name : list_fabric_presets(c.fabrics_dir)) presets.push_back(load_fabric_preset(name, c.fabrics_dir));
  if (presets.empty()) throw KioskConfigError("no fabric presets in " + c.fabrics_dir.string());
  uint32_t default_preset = presets.size();
  for (size_t i = 0; i < presets.size(); ++i)
    if (presets[i].name == c.fabric) default_preset = static_cast<uint32_t>(i);
  if (default_preset == presets.size()) load_fabric_preset(c.fabric, c.fabrics_dir);  // throws naming the known ones

  const auto log = input::stderr_log();
  input::KnobControllerOptions options;
  options.state_file = config.state_file;
  options.default_preset = default_preset;
  input::KnobController controller(input::KnobMapper(preset_looks(presets)), options, log);
  controller.restore();

  KnobSourceOptions so;
  so.sim_speed = c.speed;
  so.script_flag = c.simulate.empty() ? "--source sim" : "--simulate";
  so.log = log;
  KnobSources made;
  try {
    made = make_knob_sources(c.simulate.empty() ? config.sources : std::vector<std::string>{"sim:" + c.simulate}, config, so);
  } catch (const UnknownKnobSourceError& e) {
    throw KioskConfigError("--source: unknown source '" + e.name() + "' (hid, gpio, keyboard, sim:SCRIPT or none)");
  }
  double duration = c.duration;
  if (duration < 0 && !c.simulate.empty()) duration = made.script_seconds + 0.3;
  for (auto& s : made.sources) {
    log(LogPriority::info, "listening to " + s->describe());
    s->start(controller.sink());
  }

  // Stand-in for the frame loop: poll the channel once per 60 Hz frame, never block on it.
  const auto start = std::chrono::steady_clock::now();
  uint64_t seen = ~0ull;
  while (!stop) {
    if (duration >= 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > duration) break;
    if (controller.channel().version() != seen) {
      input::AppearanceState s;
      uint64_t v = 0;
      if (controller.channel().read(s, &v)) {
        seen = v;
        const Fabric f = apply_knobs(presets.at(s.preset_index), s);
        out << describe(f, s).dump() << std::endl;
      }
    }
    std::this_thread::sleep_for(std::chrono::microseconds(16667));
  }
  for (auto& s : made.sources) s->stop();
  controller.flush();
  return 0;
}

}  // namespace weft
