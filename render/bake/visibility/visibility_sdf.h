#pragma once
// Per-vertex visibility over the hemisphere and its signed distance function d(θ_i, φ_i)
// (seed 000 §3.2): binary visibility by ray casting, an exact Euclidean distance transform in
// the angular (θ, φ) domain, and the gradient ∇d the runtime uses to build the linear
// visibility V' of Eq. 12.
//
// Parametrisation (the vertex's thread-1 frame, docs/design.md §2 with α = 0: t = u, n' = n, b = v):
//   θ = asin(ω·u) ∈ [−π/2, π/2],  φ = atan2(ω·v, ω·n),
//   ω(θ, φ) = sin θ·u + cos θ·(cos φ·n + sin φ·v).
// The hemisphere n·ω > 0 is φ ∈ (−π/2, π/2). The stored grid is that square, N×N cells of
// side h = π/N, sample centres at −π/2 + (i+½)h. Distances are Euclidean in (θ, φ) radians,
// as the paper defines them ("the distance in the angular domain matters").
#include <cstdint>
#include <functional>
#include <vector>

#include "core/microcylinder.h"

namespace weft {

// Row-major grid over (θ, φ): index = i_θ * cols + i_φ.
template <class T>
struct AngularGrid {
  int rows = 0;  // θ samples
  int cols = 0;  // φ samples
  std::vector<T> values;
  T& at(int i_theta, int i_phi) { return values[size_t(i_theta) * cols + i_phi]; }
  const T& at(int i_theta, int i_phi) const { return values[size_t(i_theta) * cols + i_phi]; }
};

using VisibilityGrid = AngularGrid<uint8_t>;  // 1 = visible, 0 = occluded
using DistanceGrid = AngularGrid<double>;

// Angle of sample centre i on an axis starting at `start` with step h.
inline double cell_centre(double start, double h, int i) { return start + (i + 0.5) * h; }

// ω(θ, φ) in the vertex frame (see the header comment).
dvec3 direction_from_angles(const SurfaceFrame& frame, double theta, double phi);

// Ray-cast callback: true when the ray from `origin` along unit `dir` hits something.
using OcclusionQuery = std::function<bool(const dvec3& origin, const dvec3& dir)>;

// Binary visibility of one vertex on the full φ circle: resolution rows θ × 2·resolution φ,
// φ ∈ [−π, π), step h = π/resolution on both axes. Directions below the surface (n·ω ≤ 0)
// are occluded by the surface itself and are not ray cast. `origin` should already be
// offset off the surface (the caller knows the scene scale).
VisibilityGrid sample_visibility(const SurfaceFrame& frame, const dvec3& origin, int resolution,
                                 const OcclusionQuery& occluded);

// Exact squared Euclidean distance (in cells) from every cell to the nearest cell where
// `feature` is true (Felzenszwalb–Huttenlocher separable transform: a lower envelope of
// parabolas per column, then per row). `periodic_cols` wraps the column (φ) axis.
// Cells when no feature exists anywhere get +infinity.
std::vector<double> squared_distance_transform(const std::vector<uint8_t>& feature, int rows,
                                               int cols, bool periodic_cols);

// The paper's d(θ, φ) on the grid of `visibility`: +distance to the nearest occluded sample
// for visible samples, −distance to the nearest visible sample for occluded ones, in radians
// (cell side h). With `boundary_offset` each value is moved half a cell towards zero, so that
// d measures the distance to the visibility boundary (which lies between samples) rather than
// to the nearest sample across it: a half-plane aligned with the grid then gets exact d and
// |∇d| = 1. Without it this is exactly the paper's formula applied to the samples.
// A grid with no boundary at all gets ±(π, the largest angular distance): "far from any edge".
DistanceGrid signed_distance(const VisibilityGrid& visibility, double h, bool periodic_cols,
                             bool boundary_offset);

// The hemisphere part φ ∈ [−π/2, π/2) of a full-circle grid (cols = 2·rows): rows × rows.
template <class T>
AngularGrid<T> hemisphere_crop(const AngularGrid<T>& full) {
  AngularGrid<T> out{full.rows, full.cols / 2, {}};
  out.values.resize(size_t(out.rows) * out.cols);
  const int first = full.cols / 4;
  for (int i = 0; i < out.rows; ++i)
    for (int j = 0; j < out.cols; ++j) out.at(i, j) = full.at(i, first + j);
  return out;
}

// ∇d = (∂d/∂θ, ∂d/∂φ) by central differences (one-sided at non-periodic edges).
struct SdfGradient {
  DistanceGrid d_theta, d_phi;
};
SdfGradient sdf_gradient(const DistanceGrid& d, double h, bool periodic_cols);

// Everything per vertex in one call: visibility on the full circle at `resolution`
// (× `supersample`), exact boundary-offset SDF (equal to the φ-periodic full-circle one), the hemisphere
// resolution × resolution square (supersampled grids are box-filtered down, as the paper
// samples 512² and keeps 128²).
struct VertexSdf {
  DistanceGrid d;  // resolution × resolution, φ ∈ [−π/2, π/2)
  double h = 0;    // cell side in radians (π / resolution)
};
VertexSdf vertex_sdf(const SurfaceFrame& frame, const dvec3& origin, int resolution,
                     int supersample, const OcclusionQuery& occluded);

}  // namespace weft
