#include "capture/card_camera.h"

#include <cmath>

namespace weft {

std::optional<glm::dvec2> CardCamera::project(const glm::dvec3& p) const {
  const glm::dvec3 q = glm::transpose(R) * (p - C);
  if (q.z <= 1e-9) return std::nullopt;
  return glm::dvec2(f * q.x / q.z + width / 2.0, f * q.y / q.z + height / 2.0);
}

glm::dvec3 CardCamera::ray(double x, double y) const {
  const glm::dvec3 q((x - width / 2.0) / f, (y - height / 2.0) / f, 1.0);
  return glm::normalize(R * q);
}

std::optional<glm::dvec3> CardCamera::on_card(double x, double y) const {
  const glm::dvec3 d = ray(x, y);
  if (d.z > -1e-9) return std::nullopt;
  return C + d * (-C.z / d.z);
}

bool CardCamera::sees_sphere(double x, double y, const glm::dvec3& centre, double radius) const {
  const glm::dvec3 oc = C - centre, d = ray(x, y);
  const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - radius * radius;
  return b * b - c >= 0 && -b - std::sqrt(std::max(b * b - c, 0.0)) > 0;
}

CardCamera CardCamera::look_at(int width, int height, double f, const glm::dvec3& centre, const glm::dvec3& target,
                               double roll) {
  const glm::dvec3 forward = glm::normalize(target - centre);
  glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 0, 1)));
  glm::dvec3 down = glm::cross(forward, right);
  const double c = std::cos(roll), s = std::sin(roll);
  const glm::dvec3 r2 = c * right + s * down, d2 = -s * right + c * down;
  CardCamera cam;
  cam.width = width;
  cam.height = height;
  cam.f = f;
  // Columns of R are the camera axes in world: R maps camera coordinates to world directions, and
  // its transpose maps world offsets to camera coordinates.
  cam.R = glm::dmat3(r2, d2, forward);
  cam.C = centre;
  return cam;
}

}  // namespace weft
