#pragma once
// The pinhole camera that photographs the card: intrinsics (focal length f in pixels, principal
// point at the image centre, no distortion) and pose (rotation R, centre C), in the
// card's world frame (capture_card.h). Camera axes: x right, y down, z forward.
#include <optional>

#include <glm/glm.hpp>

namespace weft {

struct CardCamera {
  int width = 0, height = 0;
  double f = 0;            // pixels
  glm::dmat3 R{1.0};       // columns: the camera's right, down and forward axes in world (camera → world)
  glm::dvec3 C{0.0};       // centre, world metres

  // Continuous image position of world point p (pixel (i, j) spans [i, i+1) × [j, j+1)); nothing
  // behind the camera.
  std::optional<glm::dvec2> project(const glm::dvec3& p) const;
  // Unit world direction of the ray through image position (x, y).
  glm::dvec3 ray(double x, double y) const;
  // Where that ray meets the card's plane Z = 0, or nothing.
  std::optional<glm::dvec3> on_card(double x, double y) const;
  // Whether that ray meets the sphere (the mirror ball) in front of the camera.
  bool sees_sphere(double x, double y, const glm::dvec3& centre, double radius) const;
  glm::dvec3 right() const { return R[0]; }
  glm::dvec3 down() const { return R[1]; }
  glm::dvec3 forward() const { return R[2]; }

  // A camera at `centre` looking at `target`, its x axis level (perpendicular to +Z), turned by
  // `roll` radians about its optical axis.
  static CardCamera look_at(int width, int height, double f, const glm::dvec3& centre, const glm::dvec3& target,
                            double roll = 0.0);
};

}  // namespace weft
