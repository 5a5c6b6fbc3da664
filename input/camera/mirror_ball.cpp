#include "camera/mirror_ball.h"

#include <cmath>

namespace weft {

std::optional<glm::dvec3> MirrorBall::reflected_direction(double x, double y) const {
  const double a = (x - centre_x) / radius;
  const double b = -(y - centre_y) / radius;
  const double c2 = 1.0 - a * a - b * b;
  if (c2 < 0.0) return std::nullopt;
  const glm::dvec3 n = a * glm::dvec3(1, 0, 0) + b * glm::dvec3(0, 0, 1) + std::sqrt(c2) * view;
  return 2.0 * glm::dot(n, view) * n - view;
}

std::optional<glm::dvec2> MirrorBall::image_position(const glm::dvec3& reflected) const {
  // The normal halves the angle between R and V.
  const glm::dvec3 h = glm::normalize(reflected) + view;
  const double len = glm::length(h);
  if (len < 1e-9) return std::nullopt;  // R = −V: straight behind the ball
  const glm::dvec3 n = h / len;
  if (glm::dot(n, view) < std::cos(glm::radians(max_normal_angle_deg))) return std::nullopt;
  return glm::dvec2(centre_x + radius * n.x, centre_y - radius * n.z);
}

}  // namespace weft
