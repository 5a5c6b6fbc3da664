#pragma once
// The fabric presets a bundle gives the knobs: every fabric baked into it is a preset the fabric
// knob selects. The knobs dress the cloth objects baked in the last cloth object's fabric (a
// chair's cushions); other cloth objects keep their own (its body).
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
// The preset the knobs start from: the one they dress (0 when it is not a preset).
std::uint32_t default_preset(const SceneBundle& sb);

// Why knob positions turned for the presets shown (`looks`, starting from `start`) cannot carry
// over to `next`: its presets differ (names, colours, order) or its cloth starts from another;
// empty when they can, since each position then means the same to the shopper.
std::string knob_reset_reason(const std::vector<input::PresetLook>& looks, std::uint32_t start, const SceneBundle& next);

}  // namespace weft
