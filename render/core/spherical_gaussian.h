#pragma once
// Spherical Gaussians (DESIGN.md §3): G(ω) = μ·exp(λ(ω·ξ − 1)), μ RGB radiance, λ = 2/σ² in
// seed 000's notation. An environment is a small set of them (10 by default).
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace weft {

struct SphericalGaussian {
  glm::dvec3 axis{0, 0, 1};       // ξ, unit length
  double sharpness = 1.0;         // λ
  glm::dvec3 amplitude{1.0};      // μ (RGB)

  // Value in direction w (unit).
  glm::dvec3 operator()(const glm::dvec3& w) const {
    return amplitude * std::exp(sharpness * (glm::dot(w, axis) - 1.0));
  }
};

using SgLighting = std::vector<SphericalGaussian>;

// Radiance of a set of SGs in direction w.
glm::dvec3 evaluate(std::span<const SphericalGaussian> sgs, const glm::dvec3& w);

}  // namespace weft
