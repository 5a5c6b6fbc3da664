#include "kiosk/kiosk_look_sink.h"

#include <string>

#include "gl/gl_error.h"
#include "kiosk/kiosk_label.h"
#include "kiosk/kiosk_log.h"
#include "kiosk/knob_presets.h"

namespace weft {

KioskLookSink::KioskLookSink(std::function<void(float degrees)> turn_light) : turn_light_(std::move(turn_light)) {}

void KioskLookSink::show(SceneBundle& scene, gpu::SceneRenderer& renderer, std::vector<Fabric>& cloth_fabrics,
                         KioskLabel* label) {
  label_ = label;
  scene_ = &scene;
  renderer_ = &renderer;
  cloth_fabrics_ = &cloth_fabrics;
  colourways_.emplace(scene);
}

void KioskLookSink::wear_colourway(std::uint32_t colourway) {
  colourways_->wear(*scene_, *renderer_, *cloth_fabrics_, colourway);
}

void KioskLookSink::show_label(std::uint32_t preset, std::uint32_t colourway) {
  if (label_) label_->show(label_text(*scene_, preset, colourway));
}

void KioskLookSink::dress_cloth(const Fabric& fabric) {
  try {
    size_t c = 0;
    for (const auto& o : scene_->scene.cloth_objects()) {
      if (knobs_dress(*scene_, o)) renderer_->set_fabric(c, fabric);
      ++c;
    }
  } catch (const gpu::GpuError& e) {  // e.g. a preset the bundle baked no tables for
    kiosk_log_warning(std::string("knobs: ") + e.what() + "; keeping the fabric shown");
  }
}

}  // namespace weft
