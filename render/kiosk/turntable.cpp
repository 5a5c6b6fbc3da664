#include "kiosk/turntable.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/bounds.h"

namespace weft {

SgLighting rotated_about_z(const SgLighting& sgs, double deg) {
  const double a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
  SgLighting out = sgs;
  for (auto& g : out) g.axis = glm::dvec3(c * g.axis.x - s * g.axis.y, s * g.axis.x + c * g.axis.y, g.axis.z);
  return out;
}

glm::dvec3 turntable_pivot(const Scene& scene) {
  const Bounds b = product_bounds(scene);
  return b.empty() ? glm::dvec3(0.0) : b.centre();
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
