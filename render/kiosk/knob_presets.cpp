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

}  // namespace

std::vector<Fabric> preset_list(const SceneBundle& sb) {
  std::vector<Fabric> presets;
  for (const auto& [name, f] : sb.fabrics) presets.push_back(f);
  return presets;
}

std::string knob_fabric(const SceneBundle& sb) {
  std::string fabric;
  for (const auto& o : sb.scene.cloth_objects()) fabric = o.fabric;
  return fabric;
}

std::uint32_t default_preset(const SceneBundle& sb) {
  const auto at = sb.fabrics.find(knob_fabric(sb));
  return at != sb.fabrics.end() ? std::uint32_t(std::distance(sb.fabrics.begin(), at)) : 0;
}

std::string knob_reset_reason(const std::vector<input::PresetLook>& looks, std::uint32_t start, const SceneBundle& next) {
  const std::vector<input::PresetLook> next_looks = preset_looks(preset_list(next));
  const std::uint32_t next_start = default_preset(next);
  if (!same_looks(looks, next_looks)) return "the fabric presets differ: [" + names(looks) + "] -> [" + names(next_looks) + "]";
  if (start != next_start)
    return "the cloth wears '" + next_looks.at(next_start).name + "' instead of '" + looks.at(start).name + "'";
  return "";
}

}  // namespace weft
