#include "kiosk/kiosk_colourways.h"

#include "gl/gl_error.h"
#include "kiosk/kiosk_log.h"
#include "kiosk/kiosk_renderer.h"

namespace weft {

KioskColourways::KioskColourways(const SceneBundle& sb) : own_(cloth_looks(sb.scene)) {}

bool KioskColourways::wear(SceneBundle& sb, gpu::SceneRenderer& renderer, std::vector<Fabric>& cloth, std::uint32_t k) {
  const auto& colourways = sb.scene.colourways;
  if (colourways.empty() || long(k) == worn_ || k >= colourways.size()) return false;
  wear_looks(sb.scene, colourway_looks(sb.scene, own_, k));
  cloth = cloth_fabrics(sb);
  for (size_t c = 0; c < cloth.size(); ++c) {
    try {
      renderer.set_fabric(c, cloth[c]);
    } catch (const gpu::GpuError& e) {  // e.g. a fabric the bundle baked no tables for
      kiosk_log_warning("colourway '" + colourways[k].name + "': " + e.what() + "; that object keeps its fabric");
    }
  }
  worn_ = long(k);
  kiosk_log_info("wearing colourway '" + colourways[k].name + "'");
  return true;
}

}  // namespace weft
