#include "kiosk/knob_presets.h"

#include <iterator>

#include "kiosk/knob_appearance.h"

namespace weft {
namespace {

bool same_looks(const std::vector<input::PresetLook>& a, const std::vector<input::PresetLook>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].name != b[i].name || a[i].albedo != b[i].albedo) return false;
  return true;
}

std::string names(const std::vector<input::PresetLook>& looks) {
  std::string s;
  for (const auto& l : looks) s += (s.empty() ? "" : ", ") + l.name;
  return s;
}

// The cloth object whose fabric the knobs dress: the last one (null without cloth).
const SceneObject* dressed_object(const SceneBundle& sb) {
  const SceneObject* last = nullptr;
  for (const auto& o : sb.scene.cloth_objects()) last = &o;
  return last;
}

}  // namespace

std::vector<Fabric> preset_list(const SceneBundle& sb) {
  const SceneObject* dressed = dressed_object(sb);
  std::vector<Fabric> presets;
  for (const auto& [name, f] : sb.fabrics)
    presets.push_back(dressed && name == dressed->fabric ? object_base_fabric(*dressed, f) : f);
  return presets;
}

std::string knob_fabric(const SceneBundle& sb) {
  const SceneObject* dressed = dressed_object(sb);
  return dressed ? dressed->fabric : "";
}

bool knobs_dress(const SceneBundle& sb, const SceneObject& o) {
  const SceneObject* dressed = dressed_object(sb);
  return dressed && o.is_cloth() && o.fabric == dressed->fabric && o.colour == dressed->colour;
}

std::uint32_t default_preset(const SceneBundle& sb) {
  const auto at = sb.fabrics.find(knob_fabric(sb));
  return at != sb.fabrics.end() ? std::uint32_t(std::distance(sb.fabrics.begin(), at)) : 0;
}

namespace {

// The presets with the last of `looks` (the dressed cloth object's) on its fabric, and that preset's index.
std::pair<std::vector<Fabric>, std::uint32_t> dressed_presets(const SceneBundle& sb, const std::vector<ClothLook>& looks) {
  std::vector<Fabric> presets;
  std::uint32_t start = 0;
  for (const auto& [name, f] : sb.fabrics) {
    if (!looks.empty() && name == looks.back().fabric) {
      start = std::uint32_t(presets.size());
      presets.push_back(looks.back().colour ? product_coloured(f, *looks.back().colour) : f);
    } else {
      presets.push_back(f);
    }
  }
  return {presets, start};
}

}  // namespace

std::vector<Fabric> colourway_preset_list(const SceneBundle& sb, size_t k) {
  return dressed_presets(sb, colourway_looks(sb.scene, cloth_looks(sb.scene), k)).first;
}

std::vector<input::ColourwayPresets> colourway_presets(const SceneBundle& sb) {
  std::vector<input::ColourwayPresets> out;
  const std::vector<ClothLook> base = cloth_looks(sb.scene);
  for (size_t k = 0; k < sb.scene.colourways.size(); ++k) {
    const auto [presets, start] = dressed_presets(sb, colourway_looks(sb.scene, base, k));
    out.push_back({sb.scene.colourways[k].name, preset_looks(presets), start});
  }
  return out;
}

std::string knob_reset_reason(const std::vector<input::PresetLook>& looks, std::uint32_t start, const SceneBundle& next,
                              const std::vector<std::string>& colourways) {
  std::vector<std::string> next_colourways;
  for (const auto& c : next.scene.colourways) next_colourways.push_back(c.name);
  if (colourways != next_colourways) return "the colourways differ";
  const std::vector<input::PresetLook> next_looks = preset_looks(preset_list(next));
  const std::uint32_t next_start = default_preset(next);
  if (!same_looks(looks, next_looks)) return "the fabric presets differ: [" + names(looks) + "] -> [" + names(next_looks) + "]";
  if (start != next_start)
    return "the cloth wears '" + next_looks.at(next_start).name + "' instead of '" + looks.at(start).name + "'";
  return "";
}

}  // namespace weft
