#pragma once
// A lighting's per-object visibility, computed on the CPU when the lighting changes (the SG axes
// change only then) from what the bundle baked per vertex (the PCA of the SDF, or the visibility
// mask): what a runtime method's prepare_lighting returns (methods/cloth_method.h) and the floors'
// shading reads (methods/lambert_visibility.h).
#include <cstddef>
#include <vector>

#include "core/microcylinder.h"
#include "core/spherical_gaussian.h"
#include "methods/broad_lobe_bits.h"
#include "runtime/object_visibility.h"
#include "runtime/visibility_mask.h"
#include "scene/mesh.h"

namespace weft {

// Every vertex of an object and every SG of a lighting: the SDF d and its gradient at the SG
// axis (step 1 of methods/iwasaki/iwasaki_visibility.h), or the mask's open share. On a mesh
// with a pass subset (scene/vertex_pass_mesh.h) these are looked up at the pass vertices and
// blended from them elsewhere (the mask's bits: the heaviest corner's), as the shading is.
struct SgVisibility {
  size_t vertices = 0;
  int sgs = 0;
  std::vector<float> values;  // [vertex][sg] × (d, ∂d/∂θ', ∂d/∂φ') (radians, vertex frame)
  // The broad lobes' cell bits from the visibility mask (rungs with broad-lobe quadrature;
  // methods/broad_lobe_bits.h), computed with the values; empty (0 vertices) otherwise.
  BroadLobeBits broad;
  // `mesh`: the object's mesh (the vertex frames the bake cast from: normal + warp).
  // `above_horizon`: look each SG up where iwasaki shades it at that vertex, the axis of
  // above_horizon(G, vertex normal) (spherical_gaussian.h), instead of at its own axis.
  static SgVisibility compute(const ObjectVisibility& visibility, const TriangleMesh& mesh, const SgLighting& sgs,
                              bool above_horizon = false);
  // The mask's alternative (method iwasaki_vertex_mask): per (vertex, SG) the share V_k of the
  // SG's part above the vertex's surface that no geometry blocks, in place of d, as (V_k, 0, 0);
  // the shader multiplies the SG's amplitude by it instead of taking the SDF's H per lobe.
  static SgVisibility from_mask(const VisibilityMask& mask, const TriangleMesh& mesh, const SgLighting& sgs);
  dvec3 at(size_t vertex, int sg) const {
    const float* p = &values[(vertex * size_t(sgs) + size_t(sg)) * 3];
    return dvec3(p[0], p[1], p[2]);
  }
};

}  // namespace weft
