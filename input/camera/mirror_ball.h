#pragma once
// Mirror-ball (chrome sphere) geometry: which world direction a camera pixel on the ball sees.
//
// Camera-to-world orientation (world frame of docs/design.md §3, right-handed, +Z up): the camera
// looks along world +Y at the ball, image x (right) is world +X, image y (down) is world −Z.
// So the direction from the ball towards the camera is V = −Y, and the point of the ball
// straight in front of the camera reflects the camera itself (R = V = −Y); the ball's rim
// reflects +Y, the direction straight behind the ball. Mount the camera level, its image x
// along the showroom's +X; the scene's world frame is then the camera's.
//
// The view is orthographic (a camera far from the ball compared to its radius): a pixel at
// normalised ball coordinates a = (x − cx)/r, b = −(y − cy)/r sees the ball normal
//   N = a·X + b·Z + √(1 − a² − b²)·V,  and the reflected direction  R = 2(N·V)N − V.
// Near the rim one pixel spans a large solid angle and the reflection grazes the ball, so
// directions whose normal is more than `max_normal_angle` from V (a cap around +Y) are masked.
#include <optional>

#include <glm/glm.hpp>

namespace weft {

struct MirrorBall {
  double centre_x = 0.0;  // pixels, in image coordinates (pixel (i, j) spans [i, i+1) × [j, j+1))
  double centre_y = 0.0;
  double radius = 0.0;    // pixels
  double max_normal_angle_deg = 85.0;  // mask: normals beyond this from V (reflections > 2× that)

  static constexpr glm::dvec3 view{0.0, -1.0, 0.0};  // V: ball -> camera

  // The reflected world direction R at image position (x, y) (continuous coordinates), or
  // nothing off the ball.
  std::optional<glm::dvec3> reflected_direction(double x, double y) const;
  // The image position that reflects world direction R, or nothing where R lies in the masked
  // cap behind the ball.
  std::optional<glm::dvec2> image_position(const glm::dvec3& reflected) const;
};

}  // namespace weft
