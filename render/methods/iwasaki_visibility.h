#pragma once
// The runtime side of seed 000's visibility (§3.2, "SDF is interpolated at each pixel"): the
// bundle's per-vertex PCA expanded once at load to per-vertex grids of (d, ∂d/∂θ, ∂d/∂φ), and
// the lookup at a point inside a triangle for a direction given in a tangent sample's frame.
// The GPU (shaders/iwasaki.glsl, `sdf_in_sample_frame`) holds the same grids as one texture
// atlas and does the same steps; tests/iwasaki_parity_test.cpp pins the two.
//
// Steps for direction ω = (θ, φ) of sample frame (t, n', b) at a point with frame (n, u, v):
//  1. the vertex-frame angles θ' = asin(ω·u), φ' = atan2(ω·v, ω·n) (visibility_sdf.h's frame);
//  2. each corner's grid bilinearly at (θ', φ') (cell centres, clamped: GL_LINEAR's footprint),
//     blended with the point's barycentrics;
//  3. ∇d carried to (θ, φ) by the chain rule through ω: ∂θ'/∂ω = u/cosθ',
//     ∂φ'/∂ω = ((ω·n)v − (ω·v)n)/cos²θ'.
#include <array>
#include <cstdint>
#include <vector>

#include "bake/iwasaki_bundle.h"
#include "core/microcylinder.h"

namespace weft {

struct VertexSdfGrids {
  int resolution = 0;
  size_t vertices = 0;
  // [vertex][θ row][φ col] × RGBA: d, ∂d/∂θ', ∂d/∂φ' (radians, vertex frame), 0.
  std::vector<float> texels;
  // d from the PCA, ∇d by central differences (visibility_sdf.h's sdf_gradient).
  static VertexSdfGrids expand(const ObjectVisibility& visibility);
  // (d, ∂d/∂θ', ∂d/∂φ') of one vertex, bilinear at grid coordinates (gi, gj) already clamped to
  // [0, resolution − 1].
  dvec3 bilinear(size_t vertex, double gi, double gj) const;
};

struct SdfSample {
  double d = 0, d_dtheta = 0, d_dphi = 0;
};

// Step 1–3 above. `frame`: the point's (interpolated) frame; `corners`: the triangle's vertex
// indices; `bary`: the point's barycentrics.
SdfSample sdf_in_sample_frame(const VertexSdfGrids& grids, const SurfaceFrame& frame,
                              const std::array<uint32_t, 3>& corners, const dvec3& bary,
                              const ThreadFrame& sample, double theta, double phi);

}  // namespace weft
