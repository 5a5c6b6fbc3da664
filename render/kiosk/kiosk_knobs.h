#pragma once
// The knob panel as the kiosk reads it: the knob sources (kiosk/knob_sources.h), the controller
// that maps their events onto the bundle's fabric presets (kiosk/knob_presets.h; the state
// restored from and saved to the state file), and the newest knob state for the frame loop.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/fabric.h"
#include "kiosk/kiosk_config.h"
#include "panel/appearance_state.h"
#include "panel/knob_controller.h"
#include "panel/knob_source.h"
#include "runtime/scene_bundle.h"

namespace weft {

class KioskKnobs {
public:
  // The panel config, the sources (not listening yet) and the controller for sb's presets, its
  // state restored. state_file empty: none. Throws KioskConfigError for a bad panel or config.
  KioskKnobs(const KioskConfig& config, std::filesystem::path state_file, const SceneBundle& sb);
  ~KioskKnobs();
  KioskKnobs(const KioskKnobs&) = delete;
  KioskKnobs& operator=(const KioskKnobs&) = delete;

  void listen();  // the sources' threads start
  void stop();    // the sources stop; the state is saved

  // True when the knob state changed since the last poll (or repoll()): state() holds it.
  bool poll();
  void repoll();  // the next poll() reports the state, changed or not
  const input::AppearanceState& state() const { return state_; }

  std::vector<std::string> sources() const;  // each knob source, described (a USB panel: whether connected)
  const std::vector<Fabric>& presets() const { return presets_; }
  std::uint32_t start_preset() const { return start_preset_; }  // where sb's knobs start
  // The presets the knobs dress colourway `k` from (presets() without colourways).
  const std::vector<Fabric>& presets(std::uint32_t colourway) const;
  const std::vector<std::string>& colourway_names() const { return colourway_names_; }
  // The newest HID report's arrival (steady_clock ns since its epoch); 0: none yet.
  std::int64_t last_report_ns() const { return last_report_ns_.load(); }

  // A new bundle's presets, the positions reset to its preset (saved) because of `why` (logged).
  void reset(const SceneBundle& sb, const std::string& why);
  // The knobs back at sb's start (saved), nobody having touched them for `idle_seconds` (logged).
  void go_home(const SceneBundle& sb, double idle_seconds);

private:
  void make_controller(const SceneBundle& sb);
  void restart(const SceneBundle& sb);  // a new controller at sb's start positions, saved

  std::filesystem::path state_file_;
  input::MappingConfig mapping_;  // the panel config's choices (a dial given to the zoom)
  std::vector<Fabric> presets_;
  std::uint32_t start_preset_ = 0;
  std::vector<std::vector<Fabric>> colourway_fabrics_;  // per colourway: its presets
  std::vector<std::string> colourway_names_;
  std::uint32_t boot_preset_ = 0;  // where the knobs start without a state file: the first colourway's start
  std::unique_ptr<input::KnobController> controller_;  // replaced (render thread) when a new bundle's presets differ
  std::mutex controller_m_;                             // the sources' events vs that replacement
  std::atomic<std::int64_t> last_report_ns_{0};
  std::vector<std::unique_ptr<input::KnobSource>> sources_;
  input::AppearanceState state_;
  std::uint64_t version_ = ~0ull;
};

}  // namespace weft
