#pragma once
// Knob motion → appearance. The panel layout (input/KNOBS.md):
//   dial 0  hue of the selected thread(s)          3° per step, wraps around the colour wheel
//   dial 1  brightness (HSV value) of the selection  ×2 per 8 steps; from 1/8 of the preset up to A = 1
//   dial 2  gloss of the selection                 γ_s and γ_v together, ×2 per 8 steps, ±2 octaves
//                                                  (clockwise = glossier = narrower lobes)
//   dial 3  environment rotation                   5° per step, wraps
//   zoom    camera from the scene's view to its close-up, 8 steps (keyboard t/g, or the dial
//           MappingConfig::zoom_dial names)
//   button 0 (push dial 0)  selection: both threads → warp → weft → both
//   button 1 (push dial 1)  previous fabric preset   button 2 (push dial 2)  next fabric preset
//   button 3 (push dial 3)  environment back to 0°   button 4 (reset)  undo all edits of this fabric
//   colourway (keyboard c, or the button MappingConfig::colourway_button names)  the next colourway,
//           its fabric unedited
// Acceleration: a detent that follows the previous one on the same dial, in the same direction,
// within 50 ms counts ×2, within 20 ms ×4 (times from the source's clock, e.g. the panel's).
// State is kept as integer step counts (exact, persistable); colours are derived from them.
#include <array>
#include <string>
#include <vector>

#include "panel/appearance_state.h"
#include "panel/knob_source.h"

namespace weft::input {

// What the mapper needs to know of a fabric preset (the renderer fills it from render/core's Fabric).
struct PresetLook {
  std::string name;
  std::array<std::array<double, 3>, 2> albedo{};  // A of warp and weft, as in the preset
};

// The knobs' integer positions: what is persisted.
struct KnobPositions {
  uint32_t colourway = 0;  // with colourways: which one is worn; `preset` indexes its presets
  uint32_t preset = 0;
  ThreadSelection selection = ThreadSelection::both;
  std::array<int, 2> hue_steps{};
  std::array<int, 2> brightness_steps{};
  std::array<int, 2> gloss_steps{};
  int env_steps = 0;
  int zoom_steps = 0;  // 0: the scene's camera … MappingConfig::zoom_steps: its close-up (not persisted)
  bool operator==(const KnobPositions&) const = default;
};

struct MappingConfig {
  double hue_deg_per_step = 3.0;
  int brightness_steps_per_octave = 8;
  int brightness_min_steps = -24;  // 1/8 of the preset's value
  int gloss_steps_per_octave = 8;
  int gloss_limit_steps = 16;      // ±2 octaves of γ
  double env_deg_per_step = 5.0;
  int zoom_steps = 8;   // from the scene's camera to its close-up
  int zoom_dial = -1;   // a dial (0–3) that zooms instead of its own job; −1: none
  int colourway_button = -1;  // a button (0–4) that steps to the next colourway instead of its own job; −1: none
  uint32_t accel_x2_ms = 50;
  uint32_t accel_x4_ms = 20;
};

// One colourway as the knobs see it: its name, its presets (the same names in every colourway,
// the dressed one in the colourway's colour) and the preset its cloth starts from.
struct ColourwayPresets {
  std::string name;
  std::vector<PresetLook> presets;
  uint32_t start_preset = 0;
};

class KnobMapper {
public:
  // `presets` must not be empty.
  explicit KnobMapper(std::vector<PresetLook> presets, MappingConfig config = {});

  // Applies one event; returns true when the appearance changed.
  bool apply(const KnobEvent& event);
  // Replaces the positions (e.g. restored from disk), clamped to the limits.
  void set_positions(const KnobPositions& positions);
  const KnobPositions& positions() const { return positions_; }
  AppearanceState appearance() const;

  // With colourways (none by default) the presets are the worn colourway's, and the colourway
  // control steps through them, each starting unedited at its own preset. Each entry must have
  // presets of the same names as the mapper's. Resets the positions to the first colourway.
  void set_colourways(std::vector<ColourwayPresets> colourways);
  std::vector<std::string> colourway_names() const;

  const std::vector<PresetLook>& presets() const { return presets_; }
  // Largest brightness step for a thread of the current preset (A reaches 1 there).
  int brightness_max_steps(int thread) const;

private:
  int accelerated(int dial, int detents, uint32_t time_ms);
  void select_preset(uint32_t index);
  void wear_colourway(uint32_t index);
  void clamp();

  std::vector<PresetLook> presets_;
  std::vector<ColourwayPresets> colourways_;
  MappingConfig config_;
  KnobPositions positions_;
  uint8_t buttons_ = 0;
  std::array<uint32_t, kDialCount> last_time_{};
  std::array<int, kDialCount> last_direction_{};
};

}  // namespace weft::input
