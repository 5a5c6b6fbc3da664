#pragma once
// The kiosk's side of the look (kiosk/look_applier.h): each command carried out on the scene
// shown, the renderer drawing it, the label and the zoom the view eases to.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/fabric.h"
#include "gpu/scene_renderer.h"
#include "kiosk/kiosk_colourways.h"
#include "kiosk/look_applier.h"
#include "runtime/scene_bundle.h"

namespace weft {

class KioskLabel;

class KioskLookSink final : public LookSink {
public:
  // turn_light: how the kiosk lights the scene with its room light turned by `degrees` (off the
  // render thread once the first frame is shown).
  explicit KioskLookSink(std::function<void(float degrees)> turn_light);

  // The scene shown, in its own looks, and the renderer drawing it; `cloth_fabrics` (each cloth
  // object's base fabric, kiosk/kiosk_renderer.h) follows the colourway worn; label: null without
  // one. Called again for a new bundle, then LookApplier::new_renderer.
  void show(SceneBundle& scene, gpu::SceneRenderer& renderer, std::vector<Fabric>& cloth_fabrics, KioskLabel* label);
  double zoom_target() const { return zoom_target_; }

  void wear_colourway(std::uint32_t colourway) override;
  void show_label(std::uint32_t preset, std::uint32_t colourway) override;
  void dress_cloth(const Fabric& fabric) override;
  void aim_zoom(double zoom) override { zoom_target_ = zoom; }
  void turn_light(float degrees) override { turn_light_(degrees); }

private:
  std::function<void(float)> turn_light_;
  KioskLabel* label_ = nullptr;
  SceneBundle* scene_ = nullptr;
  gpu::SceneRenderer* renderer_ = nullptr;
  std::vector<Fabric>* cloth_fabrics_ = nullptr;
  std::optional<KioskColourways> colourways_;  // the scene's: which colourway it wears
  double zoom_target_ = 0;
};

}  // namespace weft
