#pragma once
// Each thread's resolved radiance along its visible float, seen from straight above
// (core/weave_layout.h: a float's samples lie uniformly in arc length), under directional lights
// with the swatch's warp at `turn`: what the close-up shows at each place of the weave. The
// close-up's simulator draws it; its registration predicts the folded tile from it.
#include <algorithm>
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "capture/fabric_fit.h"
#include "core/fabric.h"

namespace weft {

// [thread][arc bin]: bin b covers arc fractions [b, b + 1)/arc_bins, evaluated at its middle.
using FloatRadiance = std::array<std::vector<glm::dvec3>, 2>;

FloatRadiance float_radiance(const Fabric& fabric, const std::vector<FitLight>& lights, double turn, int arc_bins,
                             int tangent_samples);

// The bin of a float's arc fraction (WeaveSample::arc, [0, 1)).
inline int arc_bin(double arc, int arc_bins) { return std::min(static_cast<int>(arc * arc_bins), arc_bins - 1); }

}  // namespace weft
