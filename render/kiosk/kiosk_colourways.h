#pragma once
// The colourway the kiosk shows (docs/content-guide.md, "Colourways"): the knob state names one
// (input/panel/appearance_state.h); wearing it dresses the scene's cloth objects in its looks and
// gives each its new base fabric, so that the knobs then edit the colourway worn.
#include <cstdint>
#include <vector>

#include "core/fabric.h"
#include "gpu/scene_renderer.h"
#include "runtime/scene_bundle.h"

namespace weft {

class KioskColourways {
public:
  // Keeps sb's own looks: a colourway that does not name an object leaves it in its own.
  explicit KioskColourways(const SceneBundle& sb);

  // Dresses sb's scene and `renderer` in colourway `k`; `cloth` (each cloth object's base fabric,
  // kiosk/kiosk_renderer.h) follows. Nothing without colourways or when `k` is worn already.
  // True when the looks changed.
  bool wear(SceneBundle& sb, gpu::SceneRenderer& renderer, std::vector<Fabric>& cloth, std::uint32_t k);

private:
  std::vector<ClothLook> own_;
  long worn_ = -1;  // none yet
};

}  // namespace weft
