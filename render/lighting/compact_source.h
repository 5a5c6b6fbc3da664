#pragma once
// The dominant compact bright source of an environment map (a sun, a spot lamp), found so that
// the SG fit can give it exactly one lobe at its direction with its power (sg_fit.h) instead of
// leaving it to a least-squares fit of a blurred grid, which may split it over two lobes.
//
// Found by growing the 8-connected region of texels around the brightest one whose luminance
// is at least `threshold` of the peak's (the core), then one texel further (the texels its edge
// covers partly); the background is the mean radiance of the ring of texels around that. It
// counts as a compact source when the core stays within `max_radius_deg` of the peak (a few
// texels at the coarsest map the probe fits), its mean luminance is at least `min_contrast`
// times the background's, and the power above the background is at least `min_power_share` of
// the map's.
#include <optional>

#include <glm/glm.hpp>

#include "lighting/env_map.h"

namespace weft {

struct CompactSourceOptions {
  double threshold = 0.02;        // core: luminance ≥ threshold × the peak texel's
  double max_radius_deg = 6.0;    // every core texel within this angle of the peak texel
  double min_contrast = 20.0;     // core mean luminance ≥ this × the background's
  double min_power_share = 0.01;  // power above the background ≥ this × the map's power
};

struct CompactSource {
  glm::dvec3 direction{0, 0, 1};  // unit: centroid of the power above the background
  glm::dvec3 power{0.0};          // ∫(L − background) dω over the region, RGB (≥ 0)
  double spread = 0.0;            // power-weighted mean of 1 − d·direction over the region
  glm::dvec3 background{0.0};     // radiance of the ring around the region
};

// The dominant compact source of `map`, or nothing. When `without` is given and a source is
// found, it receives `map` with the region's texels set to the background, so that the map
// minus the source plus a lobe of the source's power keeps the map's power exactly.
std::optional<CompactSource> find_compact_source(const EnvMap& map, const CompactSourceOptions& options = {},
                                                 EnvMap* without = nullptr);

}  // namespace weft
