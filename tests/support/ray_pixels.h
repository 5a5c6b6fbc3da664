// Pixels the CPU side of a parity test shades by ray casting: well inside one object's
// silhouette, where the GPU's rasterised surface and the ray's hit are the same point.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "reference/ray_scene.h"
#include "scene/mesh.h"
#include "scene/scene.h"

namespace weft::test {

// True when the rays through pixel (x, y) and its 8 neighbours all hit `object`.
inline bool interior_pixel(const RayScene& rays, const Camera& camera, int width, int height, int x, int y,
                           std::size_t object) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const auto hit = rays.intersect(camera.position, camera_ray(camera, width, height, x + dx + 0.5, y + dy + 0.5));
      if (!hit || hit->object != object) return false;
    }
  return true;
}

// A triangle's position, normal and warp at barycentric `b`, as the vertex shader interpolates them.
struct MeshPoint {
  glm::dvec3 position{0}, normal{0}, warp{0};
  glm::dvec2 uv{0};  // zero for a mesh without UVs
};

inline MeshPoint mesh_point(const TriangleMesh& mesh, const std::array<uint32_t, 3>& triangle, glm::dvec3 b) {
  MeshPoint m;
  for (int k = 0; k < 3; ++k) {
    m.position += b[k] * mesh.positions[triangle[k]];
    m.normal += b[k] * mesh.normals[triangle[k]];
    m.warp += b[k] * mesh.warps[triangle[k]];
    if (!mesh.uvs.empty()) m.uv += b[k] * mesh.uvs[triangle[k]];
  }
  return m;
}

}  // namespace weft::test
