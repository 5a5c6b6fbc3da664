#pragma once
// The direction grids the weighting tables live on (seed 000 §3.1: 48×48 ξ, 48×48 ω_o).
//
// Parameterisation: the upper hemisphere (z ≥ 0 in the local frame n = +z, warp u = +x,
// weft v = +y) is mapped from the square [−1,1]² by Shirley–Chiu's concentric square→disk map
// followed by Lambert's equal-area disk→hemisphere map (z = 1 − r², xy scaled by √(2 − r²)).
// Both maps preserve area, so every cell of an N×N grid on the square covers the same solid
// angle 2π/N², and the square is continuous across the whole hemisphere (no seam, no pole),
// which is what bilinear interpolation needs. The node grids move the square's rings (below);
// continuity stays, equal area does not (nothing integrates over nodes).
//
// Two kinds of grid on that square:
//  - a node grid (tables): N×N nodes at s = −1 + 2·i/(N−1), so the horizon is on the border;
//    values between nodes are bilinear in s. Its square is the concentric one with each ring
//    moved (node_square_from_hemisphere): ring ρ = max(|s_x|, |s_y|) sits at disk radius
//      r(ρ) = ρ·(b − (b − 1)·ρ),   b = 2 − a·π/4,   a = kNodeRingHorizonSpacing = 0.2
//    (polar angle θ = 2·asin(r/√2)), so rings are 0.2× the equal-angle spacing at the horizon
//    (0.94° at 48 nodes) and ~1.7× at the zenith (6.4°; equal-area rings are 1.25× at the
//    horizon). W, and so each sample's T, is steepest in ω_o near the horizon (Q and P vanish
//    together there): on the pillow's cloth seen at n·ω_o < 0.3 the equal-area 48-node grid put
//    iwasaki 24 % off the quadrature, and rings at 0.6× still left a λ = 311 light at the pillow's
//    silhouette (ω_o 0.4–1.3° up) up to 5× too bright — two pixels, most of pillow / linen /
//    studio's error. At 0.2× that light's error on the image is 3.1 → 1.9 points, and the swatch's
//    point checks away from the horizon move by under half a point.
//  - a cell grid (quadrature): N×N cells with centres at s = −1 + (2i+1)/N on the equal-area
//    square, each of solid angle 2π/N².
// Index of (i, j) is j·N + i, i along the square's x.
#include <array>

#include <glm/glm.hpp>

namespace weft {

// Square [−1,1]² → unit direction with z ≥ 0.
glm::dvec3 hemisphere_from_square(glm::dvec2 s);
// Unit direction → square. Directions below the horizon (z < 0) are first moved onto it
// (z = 0, xy renormalised); the zero vector and non-finite input give the zenith.
glm::dvec2 square_from_hemisphere(glm::dvec3 w);

// Four nodes and their bilinear weights (sum 1).
struct BilinearTap {
  std::array<int, 4> index;
  std::array<double, 4> weight;
};

// The node grids' ring spacing at the horizon relative to equal-angle rings (see above). The
// GLSL twin is NODE_RING_B (= 2 − a·π/4) in shaders/hemisphere_grid.glsl; the parity tests pin the two.
inline constexpr double kNodeRingHorizonSpacing = 0.2;
// Names that grid in a bundle's table index (bake/T "node_grid"): tables baked on another are refused.
inline constexpr const char* kNodeGridId = "concentric rings a=0.2";
static_assert(kNodeRingHorizonSpacing == 0.2, "a new ring spacing is a new grid: change kNodeGridId with it");
// Node-grid square [−1,1]² ↔ unit direction (z ≥ 0; below the horizon as square_from_hemisphere).
glm::dvec3 hemisphere_from_node_square(glm::dvec2 s);
glm::dvec2 node_square_from_hemisphere(glm::dvec3 w);

struct HemisphereNodeGrid {
  int n = 48;
  int size() const { return n * n; }
  glm::dvec3 node(int index) const;
  BilinearTap tap(const glm::dvec3& w) const;
};

struct HemisphereCellGrid {
  int n = 96;
  int size() const { return n * n; }
  glm::dvec3 centre(int index) const;
  double solid_angle() const;  // of every cell: 2π/n²
};

}  // namespace weft
