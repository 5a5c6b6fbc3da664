#include "kiosk/turntable.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace weft {

SgLighting rotated_about_z(const SgLighting& sgs, double deg) {
  const double a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
  SgLighting out = sgs;
  for (auto& g : out) g.axis = glm::dvec3(c * g.axis.x - s * g.axis.y, s * g.axis.x + c * g.axis.y, g.axis.z);
  return out;
}

glm::dvec3 turntable_pivot(const Scene& scene) {
  const bool any_cloth = !scene.cloth_objects().empty();
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const SceneObject& o : scene.objects)
    if (o.is_cloth() || !any_cloth)
      for (const glm::dvec3& p : o.mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return lo.x <= hi.x ? 0.5 * (lo + hi) : glm::dvec3(0.0);
}

Camera turned_about_z(const Camera& camera, double deg, const glm::dvec3& pivot) {
  const double a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
  auto turn = [&](const glm::dvec3& p) {
    const glm::dvec3 d = p - pivot;
    return pivot + glm::dvec3(c * d.x - s * d.y, s * d.x + c * d.y, d.z);
  };
  Camera out = camera;
  out.position = turn(camera.position);
  out.target = turn(camera.target);
  out.up = glm::dvec3(c * camera.up.x - s * camera.up.y, s * camera.up.x + c * camera.up.y, camera.up.z);  // no roll
  return out;
}

int refresh_shares(double refresh_deg, double turn_deg) {
  if (!(refresh_deg > 0.0)) return 1;
  const double turn = std::abs(turn_deg);
  if (!(turn * kMaxRefreshShares > refresh_deg)) return kMaxRefreshShares;  // still, or nearly: values hold
  return std::max(1, int(refresh_deg / turn));
}

}  // namespace weft
