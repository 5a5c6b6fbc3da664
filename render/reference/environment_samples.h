#pragma once
// An environment map as directional samples for the reference (docs/design.md §3 orientation):
// the map is cut into a width × width/2 grid of cells in (u, v); each cell becomes one
// direction carrying the cell's radiant power ∫L dω (exact sum over the map's texels), placed
// at the cell's luminance-weighted centroid direction so a small bright light keeps its true
// direction. Deterministic; doubling `width` is the convergence step.
#include <vector>

#include "lighting/env_map.h"
#include "reference/scene_render.h"

namespace weft {

// width ≥ 2 (even); cells coarser than the map's texels merge them, finer ones are clamped to
// the map's resolution.
std::vector<DirectionalSample> environment_samples(const EnvMap& map, int width);

}  // namespace weft
