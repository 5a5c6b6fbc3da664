#include "runtime/visibility_mask.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace weft {

namespace {
// Groups at most half the lobe's σ across (their extent from centre to corner ≲ σ/2): G's second
// order expansion over a group then holds to a small fraction of its weight.
constexpr float kGroupPerSigma = 0.5f;
// A partly open group is split while G's log varies across it by more than this (λ·extent).
constexpr float kSplitBelow = 0.1f;
}

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

int hemisphere_cell_of(int resolution, const glm::dvec3& local) {
  // hemisphere_square_direction backwards: r from z = 1 − r², the diamond's (|a|, |b|) from φ,
  // the signs from x and y, then the square's (s, t) = (a − b, a + b).
  const double r = std::sqrt(std::max(0.0, 1.0 - std::min(local.z, 1.0)));
  const double phi = std::atan2(std::abs(local.y), std::abs(local.x));
  const double b = std::copysign(r * phi * 2.0 / std::numbers::pi, local.y);
  const double a = std::copysign(r - std::abs(b), local.x);
  auto cell = [&](double q) { return std::clamp(int(std::floor(0.5 * (q + 1.0) * resolution)), 0, resolution - 1); };
  return cell(a + b) * resolution + cell(a - b);
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
            std::uint64_t bits = 0;
            glm::dvec3 centre(0.0);
            for (int y = gy; y < gy + side; ++y)
              for (int x = gx; x < gx + side; ++x) {
                bits |= std::uint64_t(1) << (8 * y + x);
                centre += hemisphere_cell_direction(resolution, 8 * bx + x, 8 * by + y);
              }
            centre /= double(side * side);
            glm::dmat3 spread(0.0);
            for (int y = gy; y < gy + side; ++y)
              for (int x = gx; x < gx + side; ++x) {
                const glm::dvec3 d = hemisphere_cell_direction(resolution, 8 * bx + x, 8 * by + y) - centre;
                spread += glm::outerProduct(d, d) / double(side * side);
              }
            double radius = radius_[level];
            for (int y = gy; y < gy + side; ++y)
              for (int x = gx; x < gx + side; ++x) {
                const glm::dvec3 c = hemisphere_cell_direction(resolution, 8 * bx + x, 8 * by + y);
                radius = std::max(radius, std::acos(std::clamp(glm::dot(glm::normalize(centre), c), -1.0, 1.0)) + cell_radius(8 * bx + x, 8 * by + y));
              }
            radius_[level] = float(radius);
            // a·ω over the group's cells is at most a·centre + margin: |cos α − cos β| ≤ |α − β| from
            // the normalised centre, which is 1 − |centre| from the centre.
            margin_[level] = std::max(margin_[level], float(radius + 1.0 - glm::length(centre)));
            groups_[level].push_back(Group{bits, glm::vec3(centre), glm::mat3(spread), float(side * side)});
          }
  }
}

double MaskDirections::sg_open_share(const VisibilityMask& mask, size_t vertex, const glm::dvec3& axis_local,
                                     double sharpness) const {
  if (mask.resolution != resolution_) throw std::invalid_argument("visibility mask: directions of another resolution");
  const float lambda = float(sharpness);
  const float sigma = std::sqrt(2.0f / lambda);
  int level = 0;
  while (level < 3 && radius_[level + 1] <= kGroupPerSigma * sigma) ++level;
  constexpr float kCut = -14.0f;  // G below e^{−14} of its peak: skipped
  const glm::vec3 axis(axis_local);
  const std::uint64_t* words = &mask.words[vertex * size_t(mask.blocks())];
  float open = 0.0f, all = 0.0f;
  // A group partly open is split into its four quarters, down to single cells: G's variation
  // inside a group then weighs open and blocked cells alike.
  auto add = [&](auto&& self, int l, size_t b, int gx, int gy, std::uint64_t w) -> void {
    const int side = 1 << l;
    const Group& g = groups_[l][b * size_t(64 >> (2 * l)) + size_t((gy >> l) * (8 >> l) + (gx >> l))];
    const float c = glm::dot(g.centre, axis);
    if (lambda * (c - 1.0f + margin_[l]) < kCut) return;
    const int n = std::popcount(w & g.bits);
    if (l == 0 || n == 0 || n == side * side || lambda * radius_[l] <= kSplitBelow) {
      const float weight = std::exp(lambda * (c - 1.0f) + 0.5f * lambda * lambda * glm::dot(axis, g.spread * axis));
      open += weight * float(n);
      all += weight * g.cells;
      return;
    }
    const int half = side / 2;
    for (int q = 0; q < 4; ++q) self(self, l - 1, b, gx + (q & 1) * half, gy + (q >> 1) * half, w);
  };
  const auto& blocks = groups_[3];
  const int side = 1 << level;
  for (size_t b = 0; b < blocks.size(); ++b) {
    if (lambda * (glm::dot(blocks[b].centre, axis) - 1.0f + margin_[3]) < kCut) continue;
    const std::uint64_t w = words[b];
    for (int gy = 0; gy < 8; gy += side)
      for (int gx = 0; gx < 8; gx += side) add(add, level, b, gx, gy, w);
  }
  return all > 0.0f ? double(open / all) : 1.0;
}

}  // namespace weft
