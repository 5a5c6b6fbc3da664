#include "kiosk/look_applier.h"

#include <algorithm>

#include "kiosk/knob_appearance.h"

namespace weft {

LookApplier::LookApplier(LookSink& sink, double base_zoom, PresetsOf presets_of)
    : sink_(sink), base_zoom_(base_zoom), presets_of_(std::move(presets_of)) {}

void LookApplier::apply(const input::AppearanceState& look) {
  const bool full = !applied_;
  if (full || look.colourway != applied_->colourway) sink_.wear_colourway(look.colourway);
  const std::vector<Fabric>& presets = presets_of_(look.colourway);
  const Fabric fabric = apply_knobs(presets.at(std::min<size_t>(look.preset_index, presets.size() - 1)), look);
  // Every look shows the label again: a person sees what a knob did, whichever knob it was, and
  // it stays up along the way home.
  sink_.show_label(look.preset_index, look.colourway);
  // Dressed with every look, even one that only zooms or turns the light: a new fabric is what
  // makes the renderer recompute its kept per-vertex values at once (docs/design.md §5, "A knob,
  // a light or a zoom recomputes everything at once").
  sink_.dress_cloth(fabric);
  if (full || look.zoom != applied_->zoom) sink_.aim_zoom(std::clamp(base_zoom_ + double(look.zoom), 0.0, 1.0));
  if (!light_turn_deg_ || look.env_rotation_deg != *light_turn_deg_) {
    sink_.turn_light(look.env_rotation_deg);
    light_turn_deg_ = look.env_rotation_deg;
  }
  applied_ = look;
}

void LookApplier::new_renderer() { applied_.reset(); }

}  // namespace weft
