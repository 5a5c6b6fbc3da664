#include "scene/mesh_orientation.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <tuple>
#include <unordered_map>

#include "scene/bounds.h"
#include "scene/vertex_weld.h"

namespace weft {

namespace {

// Each vertex's id after welding by position (a UV or normal seam splits vertices a closed surface
// shares): positions rounded to a millionth of the mesh's extent.
std::vector<uint32_t> welded_ids(const TriangleMesh& mesh) {
  const Bounds b = bounds_of(mesh.positions);
  return weft::welded_ids(mesh.positions, std::max(1e-12, 1e-6 * glm::length(b.extent())), b.lo);
}

}  // namespace

MeshOrientation mesh_orientation(const TriangleMesh& mesh) {
  MeshOrientation o;
  if (mesh.positions.empty() || mesh.triangles.size() < 4) return o;
  const std::vector<uint32_t> id = welded_ids(mesh);
  // Closed and consistently wound: each directed edge once, and its reverse once.
  std::unordered_map<uint64_t, int> directed;
  directed.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = id[t[k]], b = id[t[(k + 1) % 3]];
      if (a == b) return o;  // a triangle collapsed by the weld: not a clean surface
      if (++directed[(uint64_t(a) << 32) | b] > 1) return o;
    }
  for (const auto& [edge, count] : directed)
    if (!directed.count((edge << 32) | (edge >> 32))) return o;
  o.closed = true;
  // The enclosed volume's sign, about the centroid (any origin gives the same sum when closed;
  // the centroid keeps the terms small).
  glm::dvec3 c(0.0);
  for (const auto& p : mesh.positions) c += p;
  c /= double(mesh.positions.size());
  double volume = 0.0;
  std::vector<glm::dvec3> face_sum(mesh.positions.size(), glm::dvec3(0.0));
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = mesh.positions[t[0]] - c, b = mesh.positions[t[1]] - c, d = mesh.positions[t[2]] - c;
    volume += glm::dot(a, glm::cross(b, d));
    const glm::dvec3 n = glm::cross(b - a, d - a);  // area-weighted, along the winding
    for (uint32_t v : t) face_sum[v] += n;
  }
  o.winding_inward = volume < 0.0;
  if (mesh.normals.size() == mesh.positions.size()) {
    // Outward faces: the winding's, turned where the winding points in.
    double agree = 0.0;
    for (size_t v = 0; v < face_sum.size(); ++v) {
      const double l = glm::length(face_sum[v]);
      if (l > 0.0) agree += glm::dot(glm::normalize(mesh.normals[v]), face_sum[v] / l);
    }
    o.normals_inward = o.winding_inward ? agree > 0.0 : agree < 0.0;
  }
  return o;
}

void turn_outward(std::span<std::array<uint32_t, 3>> triangles, std::span<glm::dvec3> normals, const MeshOrientation& o) {
  if (o.winding_inward)
    for (auto& t : triangles) std::swap(t[1], t[2]);
  if (o.normals_inward)
    for (auto& n : normals) n = -n;
}

}  // namespace weft
