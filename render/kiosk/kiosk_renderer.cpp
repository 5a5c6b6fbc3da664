#include "kiosk/kiosk_renderer.h"

#include <exception>
#include <string>

#include "kiosk/kiosk_log.h"

namespace weft {

std::vector<Fabric> cloth_fabrics(const SceneBundle& sb) {
  std::vector<Fabric> fabrics;
  for (const auto& o : sb.scene.cloth_objects()) fabrics.push_back(object_base_fabric(o, sb.fabrics));
  return fabrics;
}

std::unique_ptr<gpu::SceneRenderer> make_kiosk_renderer(const SceneBundle& sb, const std::vector<Fabric>& cloth,
                                                        const methods::RuntimeMethod& method,
                                                        std::shared_ptr<const IwasakiBundleData> iwasaki) {
  auto r = std::make_unique<gpu::SceneRenderer>(sb.scene, cloth, method, 16, std::move(iwasaki));
  r->set_backdrop(gpu::Backdrop::showroom);
  for (const std::string& w : r->warnings()) kiosk_log_warning("scene '" + sb.scene.name + "': " + w);
  try {
    r->set_weave(true);
  } catch (const std::exception& e) {
    kiosk_log_warning("scene '" + sb.scene.name + "': no close-up weave (" + e.what() +
                      "); the fabric level is shown up close");
  }
  return r;
}

}  // namespace weft
