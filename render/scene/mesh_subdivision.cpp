#include "scene/mesh_subdivision.h"

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace weft {

TriangleMesh subdivide_midpoint(const TriangleMesh& m) {
  const size_t nv = m.positions.size();
  const bool normals = !m.normals.empty(), uvs = !m.uvs.empty(), warps = !m.warps.empty();
  if ((normals && m.normals.size() != nv) || (uvs && m.uvs.size() != nv) || (warps && m.warps.size() != nv))
    throw std::invalid_argument("subdivide_midpoint: attribute arrays differ in length from the positions");
  TriangleMesh out = m;
  out.triangles.clear();
  out.triangles.reserve(4 * m.triangles.size());
  std::unordered_map<uint64_t, uint32_t> split;  // edge (lower index << 32 | higher) → midpoint vertex
  split.reserve(2 * m.triangles.size());
  auto midpoint = [&](uint32_t a, uint32_t b) {
    const uint64_t key = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
    auto [it, inserted] = split.emplace(key, uint32_t(out.positions.size()));
    if (!inserted) return it->second;
    if (out.positions.size() >= UINT32_MAX) throw std::length_error("subdivide_midpoint: more than 2^32 vertices");
    out.positions.push_back(0.5 * (m.positions[a] + m.positions[b]));
    glm::dvec3 n(0.0);
    if (normals) {
      n = m.normals[a] + m.normals[b];
      const double l = glm::length(n);
      n = l > 1e-12 ? n / l : m.normals[a];  // opposite normals: either end's
      out.normals.push_back(n);
    }
    if (uvs) out.uvs.push_back(0.5 * (m.uvs[a] + m.uvs[b]));
    if (warps) {
      const glm::dvec3 w = 0.5 * (m.warps[a] + m.warps[b]);
      out.warps.push_back(normals ? unit_tangent(w, n) : w / std::max(glm::length(w), 1e-300));
    }
    return it->second;
  };
  for (const auto& t : m.triangles) {
    const uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

TriangleMesh subdivide_midpoint(const TriangleMesh& mesh, int levels) {
  if (levels < 0) throw std::invalid_argument("subdivide_midpoint: levels must be >= 0");
  TriangleMesh out = mesh;
  for (int i = 0; i < levels; ++i) out = subdivide_midpoint(out);
  return out;
}

Scene refine_cloth_meshes(Scene scene, int levels) {
  for (auto& o : scene.cloth_objects()) o.mesh = subdivide_midpoint(o.mesh, levels);
  return scene;
}

}  // namespace weft
