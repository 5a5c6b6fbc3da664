#include "methods/sg_lights.h"

#include <algorithm>
#include <cmath>

namespace weft {

glm::dvec3 lift_to_cosine(const glm::dvec3& axis, const glm::dvec3& n, double h) {
  const double c = glm::dot(axis, n);
  if (c >= h) return axis;
  glm::dvec3 t = axis - c * n;
  double len = glm::length(t);
  if (len < 1e-9) {  // axis = −n: any tangent will do; pick one from the frame's smallest axis
    t = std::abs(n.x) < 0.9 ? glm::cross(n, glm::dvec3(1, 0, 0)) : glm::cross(n, glm::dvec3(0, 1, 0));
    len = glm::length(t);
  }
  return t / len * std::sqrt(1.0 - h * h) + h * n;
}

glm::dvec3 lift_above_horizon(const glm::dvec3& axis, const glm::dvec3& n) { return lift_to_cosine(axis, n, kSgHorizonCosine); }

double sg_effective_cosine(double sharpness, double c) {
  const double h = sg_hemisphere_integral(sharpness, c);
  if (!(h > 0.0)) return kSgHorizonCosine;
  return std::clamp(sg_clamped_cosine_integral(sharpness, c) / h, kSgHorizonCosine, 1.0);
}

glm::dvec3 sg_power(const SphericalGaussian& g) { return integral(g); }

}  // namespace weft
