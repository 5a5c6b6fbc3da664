#include "scene/mesh_vertex_order.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <meshoptimizer.h>

#include "scene/mesh_subdivision.h"

namespace weft {

namespace {

// The facings a vertex is grouped by: the cube's 6 face and 8 corner directions. On the showroom
// camera's view of the armchair (tests/bench/vertex_block_bench.cpp) 14 leave 53 % of the blocks
// with a visible vertex, 6 directions 62 %, 26 directions 55 %.
std::vector<glm::dvec3> facings() {
  std::vector<glm::dvec3> out;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (const int axes = (x != 0) + (y != 0) + (z != 0); axes == 1 || axes == 3)
          out.push_back(glm::normalize(glm::dvec3(x, y, z)));
  return out;
}

// Appends `group`'s vertices to `curve` in their Morton order.
void append_morton(const TriangleMesh& mesh, const std::vector<uint32_t>& group, std::vector<uint32_t>& curve) {
  std::vector<float> xyz;
  xyz.reserve(group.size() * 3);
  for (uint32_t v : group) xyz.insert(xyz.end(), {float(mesh.positions[v].x), float(mesh.positions[v].y), float(mesh.positions[v].z)});
  std::vector<unsigned> rank(group.size());  // rank[i]: group[i]'s place on the curve
  meshopt_spatialSortRemap(rank.data(), xyz.data(), group.size(), sizeof(float) * 3);
  const size_t first = curve.size();
  curve.resize(first + group.size());
  for (size_t i = 0; i < group.size(); ++i) curve[first + rank[i]] = group[i];
}

}  // namespace

std::vector<uint32_t> spatial_vertex_order(const TriangleMesh& mesh, int row) {
  const size_t count = mesh.positions.size();
  if (count == 0) return {};
  // Grouped by facing first: a thin part's two sides lie close but are seen from opposite sides.
  std::vector<std::vector<uint32_t>> groups(1);
  if (mesh.normals.size() == count) {
    const std::vector<glm::dvec3> dirs = facings();
    groups.assign(dirs.size(), {});
    for (size_t v = 0; v < count; ++v) {
      size_t best = 0;
      for (size_t k = 1; k < dirs.size(); ++k)
        if (glm::dot(mesh.normals[v], dirs[k]) > glm::dot(mesh.normals[v], dirs[best])) best = k;
      groups[best].push_back(uint32_t(v));
    }
  } else {
    groups[0].resize(count);
    for (size_t v = 0; v < count; ++v) groups[0][v] = uint32_t(v);
  }
  std::vector<uint32_t> curve;  // curve[k]: the k-th vertex of the order
  curve.reserve(count);
  for (const auto& g : groups)
    if (!g.empty()) append_morton(mesh, g, curve);

  // The texels in block order; laid out row by row instead, a block's four rows would be 256
  // vertices apart on the curve, far apart on the surface.
  const size_t width = std::min(size_t(std::max(row, 1)), count), rows = (count + width - 1) / width;
  const size_t b = size_t(kVertexTexelBlock);
  std::vector<uint32_t> new_index(count);
  size_t next = 0;
  for (size_t by = 0; by < rows; by += b)
    for (size_t bx = 0; bx < width; bx += b)
      for (size_t y = by; y < std::min(by + b, rows); ++y)
        for (size_t x = bx; x < std::min(bx + b, width); ++x)
          if (const size_t texel = y * width + x; texel < count) new_index[curve[next++]] = uint32_t(texel);
  return new_index;
}

namespace {
template <class T>
void permute(std::vector<T>& values, std::span<const uint32_t> new_index) {
  if (values.empty()) return;
  std::vector<T> out(values.size());
  for (size_t v = 0; v < values.size(); ++v) out[new_index[v]] = values[v];
  values = std::move(out);
}
}  // namespace

void permute_vertices(TriangleMesh& mesh, std::span<const uint32_t> new_index) {
  const size_t count = mesh.positions.size();
  if (new_index.size() != count) throw std::invalid_argument("permute_vertices: one new index per vertex needed");
  mesh.pass.reset();  // of the old numbering
  std::vector<bool> taken(count, false);
  for (uint32_t n : new_index) {
    if (n >= count || taken[n]) throw std::invalid_argument("permute_vertices: not a permutation");
    taken[n] = true;
  }
  for (const auto* values : {&mesh.normals, &mesh.warps})
    if (!values->empty() && values->size() != count) throw std::invalid_argument("permute_vertices: attribute count");
  if (!mesh.uvs.empty() && mesh.uvs.size() != count) throw std::invalid_argument("permute_vertices: attribute count");
  permute(mesh.positions, new_index);
  permute(mesh.normals, new_index);
  permute(mesh.uvs, new_index);
  permute(mesh.warps, new_index);
  for (auto& t : mesh.triangles)
    for (auto& v : t) {
      if (v >= count) throw std::invalid_argument("permute_vertices: a triangle's index is out of range");
      v = new_index[v];
    }
}

void order_vertices_spatially(TriangleMesh& mesh) { permute_vertices(mesh, spatial_vertex_order(mesh)); }

Scene order_scene_meshes(Scene scene) {
  for (auto& o : scene.objects) order_vertices_spatially(o.mesh);
  return scene;
}

Scene refine_and_order_meshes(Scene scene, int levels) {
  if (levels <= 0) return scene;
  scene = refine_cloth_meshes(std::move(scene), levels);
  for (auto& o : scene.objects)
    if (o.is_cloth()) order_vertices_spatially(o.mesh);
  return scene;
}

}  // namespace weft
