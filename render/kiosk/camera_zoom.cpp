#include "kiosk/camera_zoom.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "scene/weave_scale.h"

namespace weft {

Camera dolly(const Camera& from, const Camera& to, double t) {
  t = std::clamp(t, 0.0, 1.0);
  if (t <= 0.0) return from;
  if (t >= 1.0) return to;
  Camera c;
  c.target = glm::mix(from.target, to.target, t);
  const glm::dvec3 a = from.position - from.target, b = to.position - to.target;
  const double da = glm::length(a), db = glm::length(b);
  glm::dvec3 dir = glm::mix(a / da, b / db, t);
  if (!(glm::length(dir) > 1e-9)) dir = a / da;  // opposite views: keep the first
  const double distance = std::exp(glm::mix(std::log(da), std::log(db), t));
  c.position = c.target + glm::normalize(dir) * distance;
  c.up = glm::mix(from.up, to.up, t);
  if (!(glm::length(glm::cross(c.up, dir)) > 1e-9)) c.up = from.up;
  c.fov_deg = glm::mix(from.fov_deg, to.fov_deg, t);
  return c;
}

double ease_zoom(double shown, double target, double dt, double tau) {
  const double next = target + (shown - target) * std::exp(-std::max(dt, 0.0) / tau);
  return std::abs(next - target) < 1e-3 ? target : next;
}

Camera closeup_of(const Scene& scene, const std::vector<Fabric>& cloth, int height) {
  std::map<std::string, Fabric> fabrics;
  size_t c = 0;
  for (const auto& o : scene.objects)
    if (o.is_cloth() && c < cloth.size()) fabrics.emplace(o.fabric, cloth[c++]);
  return closeup_camera(scene, fabrics, height);
}

}  // namespace weft
