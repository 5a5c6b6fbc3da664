#pragma once
// Bakes an object's per-vertex visibility mask (runtime/visibility_mask.h): one shadow ray per
// cell of each vertex's hemisphere, from the vertex offset along its normal, as the reference's
// shadow rays and the SDF bake cast them (a hit on anything, the object itself included, blocks).
#include <optional>

#include "runtime/visibility_mask.h"
#include "scene/scene.h"

namespace weft {

// Empty when no ray is blocked (the object is unoccluded). `resolution`: N, a multiple of 8.
std::optional<VisibilityMask> bake_visibility_mask(const Scene& scene, size_t object, int resolution);

}  // namespace weft
