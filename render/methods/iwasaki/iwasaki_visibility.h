#pragma once
// The runtime side of the baked SDF visibility (seed 000 §3.2): the bundle's per-vertex PCA of the SDF
// d(θ', φ'), read where the lighting needs it. The lookup directions are the SG axes, which
// change only with the lighting, so d and ∇d are reconstructed per (vertex, SG) on the CPU when
// the lighting changes (SgVisibility), at the bundle's full SDF resolution, instead of
// expanding every vertex's grid for the GPU (128² cells × 16 B × 3362 vertices = 880 MB).
// The GPU (methods/iwasaki/iwasaki.glsl) gets the values as one small texture and does step 3 below;
// tests/gpu/iwasaki_parity_test.cpp pins the two.
//
// Steps for SG axis ξ_k, seen at a point with frame (n, u, v) through sample frame (t, n', b)
// at the axis's sample-frame angles (θ_k, φ_k):
//  1. per vertex, in its own frame: θ' = asin(ξ·u), φ' = atan2(ξ·v, ξ·n) (visibility_sdf.h);
//     the PCA grid (d by reconstruction, ∇d by its central differences, as sdf_gradient)
//     bilinearly at (θ', φ') (cell centres, clamped);
//  2. at a point inside a triangle: the corners' values blended with the point's barycentrics;
//  3. ∇d carried to the sample frame's (θ, φ) by the chain rule through ω = ξ_k, with the
//     point's frame: ∂θ'/∂ω = u/cosθ', ∂φ'/∂ω = ((ω·n)v − (ω·v)n)/cos²θ'.
#include <array>
#include <cstdint>
#include <vector>

#include "methods/sg_visibility.h"
#include "core/microcylinder.h"
#include "core/spherical_gaussian.h"
#include "scene/mesh.h"

namespace weft {

struct SdfSample {
  double d = 0, d_dtheta = 0, d_dphi = 0;
};

// Steps 2–3 above for SG `sg`. `frame`: the point's (interpolated) frame; `corners`: the
// triangle's vertex indices; `bary`: the point's barycentrics; (θ, φ): the SG axis in `sample`.
SdfSample sdf_in_sample_frame(const SgVisibility& visibility, int sg, const SurfaceFrame& frame,
                              const std::array<uint32_t, 3>& corners, const dvec3& bary,
                              const ThreadFrame& sample, double theta, double phi);

}  // namespace weft
