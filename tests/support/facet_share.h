// The share of an SG above a facet's plane among its part above the shading plane, by quadrature on
// the SG-warped grid (cells of equal G-mass): the independent side of the facet checks, against
// which facet_horizon_factor's closed form is measured.
#pragma once

#include <glm/glm.hpp>

#include "core/spherical_gaussian.h"

namespace weft::test {

inline double facet_share_by_quadrature(const SphericalGaussian& g, const glm::dvec3& ns, const glm::dvec3& ng) {
  const SgWarpedGrid grid(g.axis, g.sharpness, 512);
  long both = 0, shading = 0;
  for (int i = 0; i < grid.polar(); ++i) {
    const double c = grid.polar_cosine(i);
    for (int j = 0; j < grid.azimuthal(); ++j) {
      const glm::dvec3 w = grid.direction(c, j);
      if (glm::dot(w, ns) <= 0.0) continue;
      ++shading;
      if (glm::dot(w, ng) > 0.0) ++both;
    }
  }
  return shading ? double(both) / double(shading) : 1.0;
}

}  // namespace weft::test
