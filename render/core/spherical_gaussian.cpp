#include "core/spherical_gaussian.h"

namespace weft {

glm::dvec3 evaluate(std::span<const SphericalGaussian> sgs, const glm::dvec3& w) {
  glm::dvec3 sum(0.0);
  for (const auto& g : sgs) sum += g(w);
  return sum;
}

}  // namespace weft
