#include "probe/mirror_ball_unwrap.h"

#include <cmath>
#include <stdexcept>

namespace weft {

EnvMap unwrap_mirror_ball(const HdrImage& image, const MirrorBall& ball, int width, int height) {
  if (width < 4 || height < 2) throw std::invalid_argument("unwrap: map too small");
  EnvMap map(width, height);
  std::vector<char> valid(static_cast<size_t>(width) * height, 0);
  constexpr int n = 3;  // sub-samples per texel side
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::dvec3 sum(0);
      int count = 0;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const glm::dvec2 uv((x + (i + 0.5) / n) / width, 1.0 - (y + (j + 0.5) / n) / height);
          const auto p = ball.image_position(uv_to_direction(uv));
          if (!p) continue;
          sum += glm::dvec3(image.sample(p->x, p->y));
          ++count;
        }
      // A texel straddling the mask edge counts as valid when most of it is seen.
      if (count * 2 > n * n) {
        map.at(x, y) = glm::vec3(sum / static_cast<double>(count));
        valid[static_cast<size_t>(y) * width + x] = 1;
      }
    }
  // Fill the cap behind the ball from the ring around it.
  const double cap = std::cos(glm::radians(180.0 - 2.0 * ball.max_normal_angle_deg - 10.0));
  const glm::dvec3 behind = -MirrorBall::view;
  glm::dvec3 ring(0);
  double ring_weight = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (valid[static_cast<size_t>(y) * width + x] && glm::dot(map.direction(x, y), behind) > cap) {
        ring += map.solid_angle(y) * glm::dvec3(map.at(x, y));
        ring_weight += map.solid_angle(y);
      }
  const glm::vec3 fill = ring_weight > 0 ? glm::vec3(ring / ring_weight) : glm::vec3(0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (!valid[static_cast<size_t>(y) * width + x]) map.at(x, y) = fill;
  return map;
}

}  // namespace weft
