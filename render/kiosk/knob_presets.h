#pragma once
// The fabric presets a bundle gives the knobs: every fabric baked into it is a preset the fabric
// knob selects. The knobs dress the cloth objects baked in the last cloth object's fabric and
// colour (a chair's cushions); other cloth objects keep their own (its body). The dressed preset
// is the dressed object's base fabric (its product colour on it), so the knobs start from what
// the bake and the reference drew.
#include <cstdint>
#include <string>
#include <vector>

#include "core/fabric.h"
#include "panel/knob_mapping.h"
#include "runtime/scene_bundle.h"

namespace weft {

std::vector<Fabric> preset_list(const SceneBundle& sb);
// The name of the fabric the knobs dress: the last cloth object's ("" without cloth).
std::string knob_fabric(const SceneBundle& sb);
// Whether the knobs dress cloth object `o`: it wears the last cloth object's fabric and colour.
bool knobs_dress(const SceneBundle& sb, const SceneObject& o);
// The preset the knobs start from: the one they dress (0 when it is not a preset).
std::uint32_t default_preset(const SceneBundle& sb);

// The knobs' view of the bundle's colourways (none without any): for each, its presets with its
// dressed cloth in its look, and where its knobs start.
std::vector<input::ColourwayPresets> colourway_presets(const SceneBundle& sb);
// The presets of colourway `k` (as preset_list gives them for the bundle wearing it).
std::vector<Fabric> colourway_preset_list(const SceneBundle& sb, size_t k);

// Why knob positions turned for the presets shown (`looks`, starting from `start`) cannot carry
// over to `next`: its presets differ (names, colours, order), its cloth starts from another or its
// colourways differ;
// empty when they can, since each position then means the same to the shopper.
// With colourways, the names of those shown (`colourways`) must be `next`'s too.
std::string knob_reset_reason(const std::vector<input::PresetLook>& looks, std::uint32_t start, const SceneBundle& next,
                              const std::vector<std::string>& colourways = {});

}  // namespace weft
