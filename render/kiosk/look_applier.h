#pragma once
// The look as one piece: a knob state (panel/appearance_state.h) turned into the commands that
// show it. The kiosk's frame loop (the knobs' newest state), the way home (kiosk/idle_return.h)
// and the state file restored at boot or after a new bundle all hand their look to one
// LookApplier, which tells a LookSink what to do: the kiosk's sink drives the scene renderer, the
// label and the view (kiosk/kiosk_look_sink.h), a test's records the commands.
//
// A new knob: its field and its way home in input/panel, its command here.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/fabric.h"
#include "panel/appearance_state.h"

namespace weft {

class LookSink {
public:
  virtual ~LookSink() = default;
  // The scene's cloth in colourway `colourway`'s looks, each cloth object on its base fabric.
  virtual void wear_colourway(std::uint32_t colourway) = 0;
  // The label names preset `preset` of colourway `colourway`, fully shown again.
  virtual void show_label(std::uint32_t preset, std::uint32_t colourway) = 0;
  // `fabric` (the preset with the knobs' colours and gloss) on the cloth objects the knobs dress.
  virtual void dress_cloth(const Fabric& fabric) = 0;
  // The camera's way to the scene's close-up the view eases to, 0 … 1.
  virtual void aim_zoom(double zoom) = 0;
  // The room's light turned about +Z by `degrees`.
  virtual void turn_light(float degrees) = 0;
};

class LookApplier {
public:
  // The presets the knobs dress colourway `k` from (KioskKnobs::presets); never empty.
  using PresetsOf = std::function<const std::vector<Fabric>&(std::uint32_t colourway)>;
  // base_zoom: the zoom the knob's adds to (--zoom).
  LookApplier(LookSink& sink, double base_zoom, PresetsOf presets_of);

  // Shows `look`. The colourway, zoom and light commands follow only what differs from the look
  // applied last; the cloth is dressed and the label shown with every look (see apply()).
  void apply(const input::AppearanceState& look);
  // The sink's renderer was replaced (a new bundle): the next look is applied in full, except the
  // light's turn, which the new renderer was lit with (kiosk/bundle_swap.h).
  void new_renderer();

  // The look applied last; empty before the first and after new_renderer().
  const std::optional<input::AppearanceState>& applied() const { return applied_; }
  // The light's turn applied last, in degrees; empty until a look is applied.
  std::optional<float> light_turn_deg() const { return light_turn_deg_; }

private:
  LookSink& sink_;
  double base_zoom_;
  PresetsOf presets_of_;
  std::optional<input::AppearanceState> applied_;
  std::optional<float> light_turn_deg_;  // outlives renderers: each new one is lit with it
};

}  // namespace weft
