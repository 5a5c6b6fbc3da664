#include "scene/weave_scale.h"

#include <cmath>

#include "core/weave_layout.h"

namespace weft {

glm::dvec2 uv_length(const TriangleMesh& mesh) {
  if (mesh.uvs.size() != mesh.positions.size()) return {1.0, 1.0};
  glm::dvec2 sum(0.0);
  double weight = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 e1 = mesh.positions[t[1]] - mesh.positions[t[0]], e2 = mesh.positions[t[2]] - mesh.positions[t[0]];
    const glm::dvec2 d1 = mesh.uvs[t[1]] - mesh.uvs[t[0]], d2 = mesh.uvs[t[2]] - mesh.uvs[t[0]];
    const double det = d1.x * d2.y - d1.y * d2.x;  // twice the triangle's signed UV area
    if (!(std::abs(det) > 1e-14)) continue;
    // [∂P/∂u ∂P/∂v] = [e1 e2] · [d1 d2]⁻¹
    const glm::dvec3 dpdu = (e1 * d2.y - e2 * d1.y) / det, dpdv = (e2 * d1.x - e1 * d2.x) / det;
    const double w = std::abs(det);
    sum += w * glm::dvec2(glm::length(dpdu), glm::length(dpdv));
    weight += w;
  }
  if (!(weight > 0.0) || !(sum.x > 0.0) || !(sum.y > 0.0)) return {1.0, 1.0};
  return sum / weight;
}

glm::dvec2 weave_tiles_per_uv(const SceneObject& object, const Fabric& fabric) {
  if (object.weave_repeats_per_uv.x > 0.0 && object.weave_repeats_per_uv.y > 0.0) return object.weave_repeats_per_uv;
  const glm::dvec2 repeat_m = weave_repeat_cm(fabric) / 100.0;
  return uv_length(object.mesh) / repeat_m;
}

glm::dvec2 weave_repeat_metres(const SceneObject& object, const Fabric& fabric) {
  if (object.weave_repeats_per_uv.x > 0.0 && object.weave_repeats_per_uv.y > 0.0)
    return uv_length(object.mesh) / object.weave_repeats_per_uv;
  return weave_repeat_cm(fabric) / 100.0;
}

Camera closeup_camera(const Scene& scene, const std::map<std::string, Fabric>& fabrics, int height, double repeat_pixels) {
  if (scene.closeup) return *scene.closeup;
  double repeat = 0.0;
  for (const auto& o : scene.objects) {
    if (!o.is_cloth()) continue;
    const auto it = fabrics.find(o.fabric);
    if (it == fabrics.end()) continue;
    const glm::dvec2 r = weave_repeat_metres(o, object_fabric(o, it->second));
    const double smallest = std::min(r.x, r.y);
    if (repeat == 0.0 || smallest < repeat) repeat = smallest;
  }
  Camera c = scene.camera;
  const glm::dvec3 view = c.target - c.position;
  const double now = glm::length(view);
  if (repeat <= 0.0 || height < 1) return c;
  const double distance = repeat * height / (2.0 * repeat_pixels * std::tan(glm::radians(c.fov_deg) / 2.0));
  if (distance < now) c.position = c.target - view / now * distance;
  return c;
}

}  // namespace weft
