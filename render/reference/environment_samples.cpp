#include "reference/environment_samples.h"

#include <algorithm>
#include <stdexcept>

namespace weft {

std::vector<DirectionalSample> environment_samples(const EnvMap& map, int width) {
  if (width < 2 || map.width < 2 || map.height < 1) throw std::invalid_argument("environment_samples: bad size");
  const int cw = std::min(width, map.width), ch = std::max(1, std::min(width / 2, map.height));
  struct Cell {
    glm::dvec3 power{0.0}, weighted_dir{0.0}, plain_dir{0.0};
  };
  std::vector<Cell> cells(static_cast<size_t>(cw) * ch);
  for (int y = 0; y < map.height; ++y) {
    const double omega = map.solid_angle(y);
    const int cy = static_cast<int>(static_cast<long long>(y) * ch / map.height);
    for (int x = 0; x < map.width; ++x) {
      const int cx = static_cast<int>(static_cast<long long>(x) * cw / map.width);
      Cell& c = cells[static_cast<size_t>(cy) * cw + cx];
      const glm::dvec3 L(map.at(x, y));
      const glm::dvec3 d = map.direction(x, y);
      const double lum = 0.2126 * L.r + 0.7152 * L.g + 0.0722 * L.b;
      c.power += L * omega;
      c.weighted_dir += std::max(lum, 0.0) * omega * d;
      c.plain_dir += omega * d;
    }
  }
  std::vector<DirectionalSample> out;
  out.reserve(cells.size());
  for (const Cell& c : cells) {
    if (c.power == glm::dvec3(0.0)) continue;
    const glm::dvec3 d = glm::length(c.weighted_dir) > 0.0 ? c.weighted_dir : c.plain_dir;
    out.push_back({glm::normalize(d), c.power});
  }
  return out;
}

}  // namespace weft
