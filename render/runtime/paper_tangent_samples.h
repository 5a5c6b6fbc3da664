#pragma once
// How many tangent samples per thread the weighting tables are baked for by default; mizutani
// (GPU and C++) runs with the same counts, so the runtime needs this rule too.
#include <array>

#include "core/fabric.h"

namespace weft {

// The paper's tangent samples (seed 000 Table 1 gives |C_1| + |C_2| per cloth: linen 6,
// polyester 16, silk 10, velvet 8, silk shot 10; 6 for a fabric it does not list). The paper
// gives only the sum, so the split is ours: a straight thread (one tilt along its whole curve)
// gets 1 sample, since more would be copies of it, and the rest go to the curved thread; two
// curved threads share evenly. Satin (polyester) is then 15+1 instead of 8+8: its float's 2.5°
// highlight needs the samples (swatch/studio, points: 9.3 % → 2.5 % error at the same cost);
// silk crepe 9+1 instead of 5+5: 4.0 % → 2.0 %.
std::array<int, 2> paper_tangent_samples(const Fabric& fabric);

}  // namespace weft
