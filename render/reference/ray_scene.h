#pragma once
// A scene's triangles in an Embree 3 BVH: primary visibility (closest hit) and shadow rays
// (any hit). One Embree geometry per scene object, so a hit names its object directly.
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace weft {

struct RayHit {
  size_t object = 0;       // index into Scene::objects
  size_t triangle = 0;     // into that object's mesh (after repair)
  double b1 = 0, b2 = 0;   // barycentrics of vertices 1 and 2
  double distance = 0;
};

// Interpolated shading data at a hit.
struct SurfacePoint {
  glm::dvec3 position, geometric_normal, normal, warp;  // warp: zero for meshes without UVs
  glm::dvec2 uv{0.0};                                   // zero for meshes without UVs
};

class RayScene {
public:
  explicit RayScene(const Scene& scene);  // the scene must outlive this
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  std::optional<RayHit> intersect(const glm::dvec3& origin, const glm::dvec3& dir) const;
  // True when nothing blocks the ray from origin (exclusive of t < t_near) to infinity.
  bool unoccluded(const glm::dvec3& origin, const glm::dvec3& dir, double t_near = 0.0) const;
  SurfacePoint surface(const RayHit& hit) const;
  // A length to offset shadow-ray origins by: scales with the scene's size.
  double ray_epsilon() const { return epsilon_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  const Scene& scene_;
  double epsilon_ = 1e-4;
};

}  // namespace weft
