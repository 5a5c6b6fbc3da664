// A unit direction by azimuth about +z and elevation above the z = 0 plane (degrees): how the
// point studies and accuracy tests place a lobe relative to a swatch whose normal is +z.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace weft::test {

inline glm::dvec3 at_elevation(double azimuth_deg, double elevation_deg) {
  const double a = glm::radians(azimuth_deg), e = glm::radians(elevation_deg);
  return glm::dvec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
}

}  // namespace weft::test
