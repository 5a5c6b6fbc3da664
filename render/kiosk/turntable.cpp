#include "kiosk/turntable.h"

#include <cmath>

namespace weft {

SgLighting rotated_about_z(const SgLighting& sgs, double deg) {
  const double a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
  SgLighting out = sgs;
  for (auto& g : out) g.axis = glm::dvec3(c * g.axis.x - s * g.axis.y, s * g.axis.x + c * g.axis.y, g.axis.z);
  return out;
}

Camera turned_about_z(const Camera& camera, double deg) {
  const double a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
  Camera out = camera;
  const glm::dvec3 d = camera.position - camera.target;
  out.position = camera.target + glm::dvec3(c * d.x - s * d.y, s * d.x + c * d.y, d.z);
  return out;
}

}  // namespace weft
