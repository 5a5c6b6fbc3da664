#include "runtime/visibility_mask.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace weft {

glm::dvec3 hemisphere_square_direction(double s, double t) {
  // The square turned 45° onto the diamond |a| + |b| ≤ 1, then Clarberg's equal-area map of the
  // diamond onto the upper hemisphere: r = |a| + |b|, z = 1 − r², φ from the diamond's edge.
  const double a = 0.5 * (s + t), b = 0.5 * (t - s);
  const double r = std::abs(a) + std::abs(b);
  const double phi = r > 0.0 ? ((std::abs(b) - std::abs(a)) / r + 1.0) * std::numbers::pi / 4.0 : 0.0;
  const double z = 1.0 - r * r, q = r * std::sqrt(std::max(0.0, 2.0 - r * r));
  return glm::normalize(glm::dvec3(std::copysign(std::cos(phi), a) * q, std::copysign(std::sin(phi), b) * q, z));
}

glm::dvec3 hemisphere_cell_direction(int resolution, int x, int y) {
  return hemisphere_square_direction((2.0 * x + 1.0) / resolution - 1.0, (2.0 * y + 1.0) / resolution - 1.0);
}

MaskDirections::MaskDirections(int resolution) : resolution_(resolution) {
  if (resolution < 8 || resolution % 8) throw std::invalid_argument("visibility mask: resolution must be a multiple of 8");
  const int per_row = resolution / 8;
  // A cell's own extent: its centre to its corners.
  auto cell_radius = [&](int x, int y) {
    const glm::dvec3 c = hemisphere_cell_direction(resolution, x, y);
    double r = 0.0;
    for (int dy = 0; dy <= 1; ++dy)
      for (int dx = 0; dx <= 1; ++dx) {
        const glm::dvec3 corner = hemisphere_square_direction(2.0 * (x + dx) / resolution - 1.0, 2.0 * (y + dy) / resolution - 1.0);
        r = std::max(r, std::acos(std::clamp(glm::dot(c, corner), -1.0, 1.0)));
      }
    return r;
  };
  for (int level = 0; level < 4; ++level) {
    const int side = 1 << level;
    for (int by = 0; by < per_row; ++by)
      for (int bx = 0; bx < per_row; ++bx)
        for (int gy = 0; gy < 8; gy += side)
          for (int gx = 0; gx < 8; gx += side) {
            Group g{by * per_row + bx, 0, glm::dvec3(0.0), side * side};
            for (int y = gy; y < gy + side; ++y)
              for (int x = gx; x < gx + side; ++x) {
                g.bits |= std::uint64_t(1) << (8 * y + x);
                g.centre += hemisphere_cell_direction(resolution, 8 * bx + x, 8 * by + y);
              }
            g.centre = glm::normalize(g.centre);
            for (int y = gy; y < gy + side; ++y)
              for (int x = gx; x < gx + side; ++x) {
                const glm::dvec3 c = hemisphere_cell_direction(resolution, 8 * bx + x, 8 * by + y);
                radius_[level] = std::max(radius_[level], std::acos(std::clamp(glm::dot(g.centre, c), -1.0, 1.0)) +
                                                              cell_radius(8 * bx + x, 8 * by + y));
              }
            groups_[level].push_back(g);
          }
  }
}

double MaskDirections::sg_open_share(const VisibilityMask& mask, size_t vertex, const glm::dvec3& axis_local,
                                     double sharpness) const {
  if (mask.resolution != resolution_) throw std::invalid_argument("visibility mask: directions of another resolution");
  // The coarsest grouping over which G varies by under ~10 %: λ·r ≤ 0.1 (G's log changes by up to λ
  // per radian where its level lines cross a group, e.g. at the horizon under a zenith lobe).
  int level = 0;
  while (level < 3 && sharpness * radius_[level + 1] <= 0.1) ++level;
  constexpr double kCut = -14.0;  // G below e^{−14} of its peak: skipped
  const std::uint64_t* words = &mask.words[vertex * size_t(mask.blocks())];
  const double block_radius = radius_[3];
  double open = 0.0, all = 0.0;
  const auto& blocks = groups_[3];
  const auto& groups = groups_[level];
  const size_t per_block = groups.size() / blocks.size();
  for (size_t b = 0; b < blocks.size(); ++b) {
    const double angle = std::acos(std::clamp(glm::dot(blocks[b].centre, axis_local), -1.0, 1.0));
    if (sharpness * (std::cos(std::max(0.0, angle - block_radius)) - 1.0) < kCut) continue;
    const std::uint64_t w = words[b];
    for (size_t i = b * per_block; i < (b + 1) * per_block; ++i) {
      const Group& g = groups[i];
      const double e = sharpness * (glm::dot(g.centre, axis_local) - 1.0);
      if (e < kCut) continue;
      const double weight = std::exp(e);
      open += weight * std::popcount(w & g.bits);
      all += weight * g.cells;
    }
  }
  return all > 0.0 ? open / all : 1.0;
}

}  // namespace weft
