#pragma once
// Per-vertex visibility as one bit per direction of a fixed set: the upper hemisphere of the
// vertex's frame (normal n, warp u, v = n × u) in the equal-area octahedral map (Clarberg 2008,
// the square turned 45° onto the hemisphere's diamond), N × N cells of equal solid angle 2π/N².
// The hemisphere rather than the sphere: the cells below the vertex's own surface would all be
// blocked (iwasaki cuts lobes at the surface's horizon itself), so the hemisphere gets twice
// the angular resolution for the same bits; N = 64 gives cells of ≈ 2.2°, about the width of a
// sun's lobe (λ = 1000: σ ≈ 1.8°). Equal area: the share of an SG that no geometry blocks is a
// plain G-weighted sum of bits. Bits are stored in 8 × 8 blocks of cells, one 64-bit word each,
// so coarser groups of cells (2×2, 4×4, 8×8) are popcounts of masked words.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/spherical_gaussian.h"

namespace weft {

struct VisibilityMask {
  int resolution = 0;                 // N, a multiple of 8; cells N², blocks (N/8)²
  std::vector<std::uint64_t> words;   // [vertex][block]: bit 8·(y mod 8) + (x mod 8) of block (y/8, x/8): cell open
  int blocks() const { return (resolution / 8) * (resolution / 8); }
  size_t vertex_count() const { return resolution ? words.size() / size_t(blocks()) : 0; }
  bool open(size_t vertex, int x, int y) const {
    const std::uint64_t w = words[vertex * blocks() + (y / 8) * (resolution / 8) + x / 8];
    return (w >> (8 * (y % 8) + x % 8)) & 1u;
  }
  void set_open(size_t vertex, int x, int y) {
    words[vertex * blocks() + (y / 8) * (resolution / 8) + x / 8] |= std::uint64_t(1) << (8 * (y % 8) + x % 8);
  }
};

// The resolution the bake uses when masks are asked for (cells of ≈ 2.2°).
inline constexpr int kMaskResolution = 64;

// The direction at square point (s, t) ∈ [−1, 1]² in the vertex frame's (u, v, n) coordinates
// (z ≥ 0); cell (x, y)'s centre is s = (2x + 1)/N − 1, t = (2y + 1)/N − 1.
glm::dvec3 hemisphere_square_direction(double s, double t);
glm::dvec3 hemisphere_cell_direction(int resolution, int x, int y);
// The cell (x, y) holding direction `local` (unit, z ≥ 0; the inverse of the map above), as
// y·N + x.
int hemisphere_cell_of(int resolution, const glm::dvec3& local);

// The share of G's part above the vertex's surface that no geometry blocks: Σ bit·G / Σ G over
// the cells (equal solid angle), G in the vertex frame (`axis_local`: its axis in (u, v, n)).
// Cells are summed in groups (2×2 … 8×8 cells, each group's open count a popcount of a masked
// word), the coarsest whose extent is at most kGroupPerSigma of the lobe's σ = √(2/λ), G's sum over
// a group from its cells' mean and covariance; a group partly open is split down to single cells.
// Groups where G < e^{−14} of its peak are skipped. Float arithmetic.
// 1 when G has no weight above the surface.
class MaskDirections {
public:
  explicit MaskDirections(int resolution);
  int resolution() const { return resolution_; }
  double sg_open_share(const VisibilityMask& mask, size_t vertex, const glm::dvec3& axis_local, double sharpness) const;

private:
  struct Group {
    std::uint64_t bits;
    glm::vec3 centre;  // the mean of its cells' directions
    glm::mat3 spread;  // their covariance: Σ_cells e^{λa·ω} = cells·e^{λa·centre + λ²aᵀ·spread·a/2} to second order
    float cells;
  };
  int resolution_;
  std::vector<Group> groups_[4];  // 1×1, 2×2, 4×4, 8×8 cells, in block order
  float radius_[4] = {};          // the largest angle from a group's centre to a point of its cells
  float margin_[4] = {};          // the most a·ω exceeds a·centre over a group's cells, any unit a
};

}  // namespace weft
