// The kiosk's side of a bundle hot swap: asking the swap worker (kiosk/bundle_swap.h) for a
// prepared bundle each tick and showing it, with the knobs carried over or reset. Kiosk's own
// members, kept here so kiosk.cpp reads as its steps.
#include "kiosk/kiosk.h"

#include "kiosk/camera_zoom.h"
#include "kiosk/kiosk_knobs.h"
#include "kiosk/kiosk_light_probe.h"
#include "kiosk/kiosk_lighting.h"
#include "kiosk/kiosk_log.h"
#include "kiosk/kiosk_renderer.h"
#include "kiosk/knob_appearance.h"
#include "kiosk/knob_presets.h"
#include "kiosk/turntable.h"

namespace weft {

bool Kiosk::poll_bundle() {
  if (!swap_) return false;
  BundleSwap::Step step = [&] {
    // The probe's room light outlives the bundle; without a probe fit the new bundle's SGs light it.
    const SgLighting* room = probe_ && probe_->updates() > 0 ? &room_light_ : nullptr;
    return swap_->poll({scene_->scene.name, shown_.file, room, look_applier_.light_turn_deg().value_or(0.0f), light_version_});
  }();
  if (step.refused) notifier_.status("showing '" + scene_->scene.name + "'; the new bundle was refused (see journal)");
  if (!step.ready) return false;
  show_swapped(std::move(*step.ready));
  return true;
}

void Kiosk::show_swapped(BundleSwap::Ready r) {
  const std::string knobs_differ =
      knob_reset_reason(preset_looks(knobs_->presets()), knobs_->start_preset(), r.bundle.scene, knobs_->colourway_names());
  lighting_->retire(std::move(renderer_));
  renderer_ = std::move(r.renderer);
  cloth_fabrics_ = std::move(r.cloth_fabrics);
  method_ = r.method;
  shading_ = r.bundle.shading;
  room_light_ = r.room_light;
  scene_ = std::move(r.bundle.scene);
  look_sink_.show(*scene_, *renderer_, cloth_fabrics_, label_.get());
  look_applier_.new_renderer();
  closeup_ = closeup_of(scene_->scene, cloth_fabrics_, height_);
  pivot_ = turntable_pivot(scene_->scene);
  arm_weave_range(*renderer_, *scene_, closeup_, width_, height_);
  shown_ = {config_.bundle, false, ""};
  if (knobs_differ.empty())
    kiosk_log_info("knob state carried over (the same fabric presets and the same fabric on the cloth)");
  else
    knobs_->reset(*scene_, knobs_differ);
  // A new scene is metered as at boot, before the knobs dress it.
  meter_as_baked();
  // The knobs onto the new renderer: the same positions, or the reset ones.
  knobs_->repoll();
  if (!poll_knobs()) look_applier_.apply(knobs_->state());
  if (light_version_ != r.light_version) relight(rotated_about_z(room_light_, look_applier_.light_turn_deg().value_or(0.0f)));
}

}  // namespace weft
