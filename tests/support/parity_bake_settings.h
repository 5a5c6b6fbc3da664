// Small, fast weighting-table bake settings for the GLSL↔C++ parity tests: parity needs the same
// tables on both sides, not converged ones.
#pragma once

#include "bake/tables/weighting_bake.h"

namespace weft::test {

inline BakeSettings parity_bake_settings() {
  BakeSettings s;
  s.tangent_samples = {2, 3};
  s.xi_resolution = s.wo_resolution = s.wi_resolution = 16;
  s.lambda_levels = 4;
  s.lambda_min = 2.0;
  s.lambda_max = 256.0;
  return s;
}

}  // namespace weft::test
