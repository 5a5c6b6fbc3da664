// A random unit direction, uniform over the sphere: a point drawn in the cube, kept inside the unit
// ball and away from its centre (where normalising loses precision), then normalised. The parity
// tests draw their frames, lights and views with it.
#pragma once

#include <random>

#include <glm/glm.hpp>

namespace weft::test {

inline glm::dvec3 random_unit(std::mt19937& rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (;;) {
    const glm::dvec3 v(2 * u01(rng) - 1, 2 * u01(rng) - 1, 2 * u01(rng) - 1);
    if (glm::length(v) > 0.2 && glm::length(v) < 1.0) return glm::normalize(v);
  }
}

}  // namespace weft::test
