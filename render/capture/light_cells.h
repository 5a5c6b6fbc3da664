#pragma once
// An environment map as the directional lights the fabric fit sums, fine where the light is and
// coarse where it is not: the map is cut into `coarsest` × coarsest/2 cells in (u, v) (the
// reference renderer's sampling, reference/environment_samples.h), and a cell holding more than
// `share` of the luminous power above the horizon is split into four, down to `finest` ×
// finest/2. Each cell becomes one light carrying its power ∫L dω at its luminance-weighted
// centroid. A sharp highlight sees the lamp as finely as the reference does, at a fraction of
// the lights a uniform fine grid needs (the fit's time is linear in them).
#include <vector>

#include "capture/fabric_fit.h"
#include "lighting/env_map.h"

namespace weft {

struct LightCellOptions {
  int coarsest = 16;
  int finest = 64;       // coarsest · 2^k, and at most the map's width
  double share = 0.004;  // of the luminous power above the horizon
};

// The lights above the horizon (+Z). Throws std::invalid_argument for sizes that do not nest.
std::vector<FitLight> light_cells(const EnvMap& map, const LightCellOptions& options = {});

}  // namespace weft
