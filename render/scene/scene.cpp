#include "scene/scene.h"

#include <cmath>

namespace weft {

glm::dvec3 camera_ray(const Camera& c, int width, int height, double px, double py) {
  const glm::dvec3 forward = glm::normalize(c.target - c.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, c.up));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tan_half = std::tan(0.5 * c.fov_deg * 3.14159265358979323846 / 180.0);
  const double aspect = double(width) / height;
  const double sx = (2.0 * px / width - 1.0) * tan_half * aspect;
  const double sy = (1.0 - 2.0 * py / height) * tan_half;
  return glm::normalize(forward + sx * right + sy * up);
}

void check_camera(const Camera& c, const std::string& where) {
  if (!(c.fov_deg > 1.0 && c.fov_deg < 170.0))
    throw SceneError(where + ".fov_deg: must be in (1, 170) degrees, got " + std::to_string(c.fov_deg));
  const glm::dvec3 view = c.target - c.position;
  if (!(glm::length(view) > 1e-9)) throw SceneError(where + ": position and target coincide");
  if (!(glm::length(glm::cross(view, c.up)) > 1e-9 * glm::length(view)))
    throw SceneError(where + ".up: zero or parallel to the view direction");
}

Fabric object_fabric(const SceneObject& o, Fabric fabric) {
  if (o.optical_thickness > 0.0) fabric.optical_thickness = o.optical_thickness;
  return fabric;
}

Fabric object_base_fabric(const SceneObject& o, Fabric fabric) {
  return o.colour ? product_coloured(std::move(fabric), *o.colour) : fabric;
}

Fabric object_base_fabric(const SceneObject& o, const std::map<std::string, Fabric>& fabrics) {
  const auto it = fabrics.find(o.fabric);
  if (it == fabrics.end()) throw std::out_of_range("no fabric '" + o.fabric + "' for cloth object '" + o.name + "'");
  return object_base_fabric(o, it->second);
}

}  // namespace weft
