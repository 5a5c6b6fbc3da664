#pragma once
// The swatch's shading frame on the card: flat (+Z up), its warp turned by `turn` radians about
// +Z from the card's +X. Every view of the capture (the photos, the close-up, the fit's model of
// both, the appearance check) puts the fabric on it.
#include <cmath>

#include "core/microcylinder.h"

namespace weft {

inline SurfaceFrame swatch_frame(double turn) {
  return {{0, 0, 1}, {std::cos(turn), std::sin(turn), 0}, {-std::sin(turn), std::cos(turn), 0}};
}

}  // namespace weft
