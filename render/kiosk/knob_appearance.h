#pragma once
// The renderer's side of the knob hand-off: what the knob mapper needs from the fabric presets,
// and the preset with the knobs' AppearanceState applied (docs/design.md §2: a knob edit changes A and
// the gloss pair γ_s, γ_v of one thread, kept at their ratio).
#include <vector>

#include "core/fabric.h"
#include "panel/appearance_state.h"
#include "panel/knob_mapping.h"

namespace weft {

std::vector<input::PresetLook> preset_looks(const std::vector<Fabric>& presets);
Fabric apply_knobs(const Fabric& preset, const input::AppearanceState& state);

}  // namespace weft
