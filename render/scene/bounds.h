#pragma once
// Axis-aligned bounds: of points (a mesh's positions), and of the product a scene shows (what
// the camera frames and the turntable turns about).
#include <limits>
#include <span>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace weft {

struct Bounds {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

  bool empty() const { return !(lo.x <= hi.x); }
  void add(const glm::dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
  void add(std::span<const glm::dvec3> points) {
    for (const glm::dvec3& p : points) add(p);
  }
  glm::dvec3 centre() const { return 0.5 * (lo + hi); }
  glm::dvec3 extent() const { return hi - lo; }
};

inline Bounds bounds_of(std::span<const glm::dvec3> points) {
  Bounds b;
  b.add(points);
  return b;
}

// The scene's cloth objects' bounds, or every object's where it has no cloth.
inline Bounds product_bounds(const Scene& scene) {
  const bool any_cloth = !scene.cloth_objects().empty();
  Bounds b;
  for (const SceneObject& o : scene.objects)
    if (o.is_cloth() || !any_cloth) b.add(o.mesh.positions);
  return b;
}

}  // namespace weft
