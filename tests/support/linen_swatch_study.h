// The setup the broad-lobe point studies share (docs/research/iwasaki.md, "What limits broad lobes"): the linen
// swatch's grid-32 tables at 3+3 tangent samples, the same model at 64 samples as the converged
// side, and the four views every study reads.
#pragma once

#include <vector>

#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "core/fabric.h"
#include "support/sky_direction.h"

namespace weft::test {

struct LinenSwatchStudy {
  Fabric linen = load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  BakeSettings settings = [] {
    BakeSettings s;
    s.tangent_samples = {3, 3};
    s.xi_resolution = s.wo_resolution = s.wi_resolution = 32;
    s.lambda_levels = 8;
    return s;
  }();
  WeightingTables tables = bake_weighting_tables(linen, settings);
  ClothBsdf approx{linen, settings.tangent_samples};
  ClothBsdf exact{linen, 64};
  std::vector<glm::dvec3> views{{0, 0, 1}, {0.3, 0.2, 0.93}, {-0.6, 0.3, 0.74}, {0.2, -0.9, 0.3}};
};

}  // namespace weft::test
