#include "kiosk/knob_appearance.h"

namespace weft {

std::vector<input::PresetLook> preset_looks(const std::vector<Fabric>& presets) {
  std::vector<input::PresetLook> looks;
  for (const Fabric& f : presets) {
    input::PresetLook look;
    look.name = f.name;
    for (int t = 0; t < 2; ++t)
      for (int k = 0; k < 3; ++k) look.albedo[t][k] = f.threads[t].albedo[k];
    looks.push_back(look);
  }
  return looks;
}

Fabric apply_knobs(const Fabric& preset, const input::AppearanceState& state) {
  Fabric f = preset;
  for (int t = 0; t < 2; ++t) {
    const input::ThreadAppearance& a = state.thread[t];
    f.threads[t].albedo = dvec3(a.albedo[0], a.albedo[1], a.albedo[2]);
    f.threads[t].gamma_s = preset.threads[t].gamma_s * a.gamma_scale;
    f.threads[t].gamma_v = preset.threads[t].gamma_v * a.gamma_scale;
  }
  return f;
}

}  // namespace weft
