#pragma once
// The thin-occluder stress case's shadow region (the teapot scene): which cloth pixels
// of the scene camera's view lie in the shadow of the lighting's sun, the SG of highest peak
// radiance, found by one Embree ray per pixel toward its axis. It depends on the geometry and
// the SGs only, never on a method, so it can score every method's shadows alike.
#include <vector>

#include "core/spherical_gaussian.h"
#include "scene/scene.h"

namespace weft::bench {

struct ShadowMask {
  SphericalGaussian sun;       // the SG whose axis the rays follow
  std::vector<bool> shadow;    // cloth pixel whose point sees the sun's axis blocked by the scene
  std::vector<bool> band;      // sunlit cloth pixel within band_px (Chebyshev) of a shadow pixel
  size_t shadow_pixels = 0, band_pixels = 0;
};

// Pixel centres as the reference renderer shoots them (camera_ray at x+½, y+½). Cloth facing
// away from the sun (self-shadowed) is in neither mask: that shadow is not an occluder's.
ShadowMask sun_shadow_mask(const Scene& scene, const SgLighting& sgs, int width, int height, int band_px = 3);

}  // namespace weft::bench
