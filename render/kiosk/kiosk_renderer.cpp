#include "kiosk/kiosk_renderer.h"

#include <exception>
#include <string>

#include "kiosk/camera_zoom.h"
#include "kiosk/kiosk_log.h"
#include "kiosk/turntable.h"

namespace weft {

std::vector<Fabric> cloth_fabrics(const SceneBundle& sb) {
  std::vector<Fabric> fabrics;
  for (const auto& o : sb.scene.cloth_objects()) fabrics.push_back(object_base_fabric(o, sb.fabrics));
  return fabrics;
}

std::unique_ptr<gpu::SceneRenderer> make_kiosk_renderer(const SceneBundle& sb, const std::vector<Fabric>& cloth,
                                                        const methods::RuntimeMethod& method,
                                                        std::shared_ptr<const ShadingData> shading) {
  auto r = std::make_unique<gpu::SceneRenderer>(sb.scene, cloth, method, 16, std::move(shading));
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

void arm_weave_range(gpu::SceneRenderer& renderer, const SceneBundle& sb, const Camera& closeup, int width, int height) {
  if (!renderer.weave()) return;
  // The dolly's distance is geometric in the zoom: 64 steps move the eye a few per cent of its
  // distance each (SceneRenderer::kWeaveRangeMargin covers a tenth).
  constexpr int kSteps = 64;
  const glm::dvec3 pivot = turntable_pivot(sb.scene);
  std::vector<gpu::SceneRenderer::OrbitingCamera> path;
  for (int i = 0; i <= kSteps; ++i) {
    const double t = double(i) / kSteps;
    const Camera c = dolly(sb.scene.camera, closeup, t);
    path.push_back({c, glm::mix(pivot, c.target, t)});
  }
  const size_t reachable = renderer.set_weave_range(path, width, height);
  size_t cloth = 0;
  for (const auto& o : sb.scene.objects) cloth += o.is_cloth() ? 1 : 0;
  if (reachable < cloth)
    kiosk_log_info("scene '" + sb.scene.name + "': " + std::to_string(cloth - reachable) + " of " + std::to_string(cloth) +
                   " cloth objects never come close enough to show their weave: no weave work for them");
}

}  // namespace weft
