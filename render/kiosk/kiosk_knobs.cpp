#include "kiosk/kiosk_knobs.h"

#include "journal/journal_log.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/kiosk_log.h"
#include "kiosk/knob_appearance.h"
#include "kiosk/knob_presets.h"
#include "kiosk/knob_sources.h"
#include "panel/hid_knob_source.h"
#include "panel/knob_state_file.h"
#include "panel/panel_config.h"

namespace weft {

KioskKnobs::KioskKnobs(const KioskConfig& config, std::filesystem::path state_file, const SceneBundle& sb)
    : state_file_(std::move(state_file)) {
  input::PanelConfig panel;
  if (!config.panel_config.empty()) {
    try {
      panel = input::parse_panel_config(read_config_file(config.panel_config, "--panel-config"), config.panel_config);
    } catch (const input::PanelConfigError& e) {
      throw KioskConfigError(e.what());
    }
  }
  mapping_.zoom_dial = panel.zoom_dial;
  mapping_.colourway_button = panel.colourway_button;
  make_controller(sb);
  controller_->restore();

  KnobSourceOptions so;
  so.sim_speed = config.sim_speed;
  so.last_report_ns = &last_report_ns_;
  so.log = stderr_sink("weft run");
  const bool from_panel_config = config.panel.empty();
  try {
    sources_ = make_knob_sources(from_panel_config ? panel.sources : std::vector<std::string>{config.panel}, panel, so).sources;
  } catch (const UnknownKnobSourceError& e) {
    if (from_panel_config)
      throw KioskConfigError(config.panel_config + ": sources: expected hid, gpio, keyboard, sim:SCRIPT or none, got '" +
                             e.name() + "'");
    throw KioskConfigError("--panel: expected hid, gpio, keyboard, sim:SCRIPT or none, got '" + e.name() + "'");
  }
}

KioskKnobs::~KioskKnobs() = default;

void KioskKnobs::make_controller(const SceneBundle& sb) {
  presets_ = preset_list(sb);
  start_preset_ = default_preset(sb);
  input::KnobMapper mapper(preset_looks(presets_), mapping_);
  std::vector<input::ColourwayPresets> colourways = colourway_presets(sb);
  colourway_fabrics_.clear();
  colourway_names_.clear();
  for (size_t k = 0; k < colourways.size(); ++k) {
    colourway_fabrics_.push_back(colourway_preset_list(sb, k));
    colourway_names_.push_back(colourways[k].name);
  }
  input::KnobControllerOptions ko;
  ko.state_file = state_file_;
  boot_preset_ = colourways.empty() ? start_preset_ : colourways.front().start_preset;
  ko.default_preset = boot_preset_;
  mapper.set_colourways(std::move(colourways));
  controller_ = std::make_unique<input::KnobController>(std::move(mapper), ko, stderr_sink("weft run"));
}

const std::vector<Fabric>& KioskKnobs::presets(std::uint32_t colourway) const {
  return colourway_fabrics_.empty() ? presets_ : colourway_fabrics_.at(std::min<size_t>(colourway, colourway_fabrics_.size() - 1));
}

std::vector<std::string> KioskKnobs::sources() const {
  std::vector<std::string> out;
  for (const auto& s : sources_) {
    const auto* hid = dynamic_cast<const input::HidKnobSource*>(s.get());
    out.push_back(s->describe() + (hid ? (hid->connected() ? ": connected" : ": not connected") : ""));
  }
  return out;
}

void KioskKnobs::listen() {
  for (auto& s : sources_) {
    kiosk_log_info("listening to " + s->describe());
    s->start([this](const input::KnobEvent& e) {
      std::lock_guard lock(controller_m_);
      controller_->on_event(e);
    });
  }
}

void KioskKnobs::stop() {
  for (auto& s : sources_) s->stop();
  controller_->flush();
}

bool KioskKnobs::poll() {
  if (controller_->channel().version() == version_) return false;
  uint64_t v = 0;
  if (!controller_->channel().read(state_, &v)) return false;  // writer mid-update: next tick
  version_ = v;
  return true;
}

void KioskKnobs::repoll() { version_ = ~0ull; }

void KioskKnobs::reset(const SceneBundle& sb, const std::string& why) {
  std::lock_guard lock(controller_m_);
  restart(sb);
  kiosk_log_warning("knob state reset to preset '" + preset_looks(presets_).at(start_preset_).name + "' (" + why + ")");
}

void KioskKnobs::go_home(const SceneBundle& sb, double idle_seconds) {
  std::lock_guard lock(controller_m_);
  restart(sb);
  kiosk_log_info("knobs idle for " + std::to_string(long(idle_seconds)) + " s: easing back to preset '" +
                 preset_looks(presets_).at(start_preset_).name + "'");
}

void KioskKnobs::restart(const SceneBundle& sb) {
  controller_.reset();  // saves what the old presets' knobs had pending
  make_controller(sb);
  if (!state_file_.empty()) {
    input::KnobPositions start;
    start.preset = boot_preset_;
    std::string error;
    if (!input::write_file_atomically(state_file_, input::knob_state_text(start, preset_looks(presets(0)), colourway_names_), error))
      kiosk_log_warning("could not save the reset knob state (" + error + ")");
  }
  controller_->restore();
  version_ = ~0ull;  // the new controller counts its own versions: the next poll reports its state
}

}  // namespace weft
