// The bake's spatial vertex order (scene/mesh_vertex_order.h) on the showroom's armchair and on
// grids whose vertex counts fill no whole row or block:
//  - the ordered mesh is the same surface: the same vertices (position, normal, UV, warp
//    together) and the same triangles as triples of positions in their winding;
//  - the per-vertex passes' 4×4 texel blocks (vertex i at texel (i mod 256, i div 256)) hold
//    nearby vertices: their mean distance to the block's centroid falls well below the glTF's.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>
#include <vector>

#include "scene/mesh_vertex_order.h"
#include "scene/procedural_meshes.h"
#include "scene/scene_file.h"

using namespace weft;

namespace {

using Vertex = std::array<double, 11>;  // position, normal, UV, warp
std::vector<Vertex> vertices(const TriangleMesh& m) {
  std::vector<Vertex> out;
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const glm::dvec3 p = m.positions[i], n = m.normals[i], w = m.warps[i];
    const glm::dvec2 uv = m.uvs.empty() ? glm::dvec2(0.0) : m.uvs[i];
    out.push_back({p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y, w.x, w.y, w.z});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Each triangle as its corners' positions, rotated to start at the least (winding kept).
using Corners = std::array<std::tuple<double, double, double>, 3>;
std::vector<Corners> triangles(const TriangleMesh& m) {
  std::vector<Corners> out;
  for (const auto& t : m.triangles) {
    Corners c;
    for (int k = 0; k < 3; ++k) c[k] = {m.positions[t[k]].x, m.positions[t[k]].y, m.positions[t[k]].z};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

void expect_same_surface(const TriangleMesh& given, const TriangleMesh& ordered, const std::string& name) {
  ASSERT_EQ(ordered.positions.size(), given.positions.size()) << name;
  ASSERT_EQ(ordered.triangles.size(), given.triangles.size()) << name;
  EXPECT_EQ(ordered.uvs.size(), given.uvs.size()) << name;
  EXPECT_TRUE(vertices(ordered) == vertices(given)) << name << ": not the same vertices";
  EXPECT_TRUE(triangles(ordered) == triangles(given)) << name << ": not the same triangles";
}

// Mean distance of a vertex to its 4×4 texel block's centroid, over the blocks of a 256-wide grid.
double block_spread(const TriangleMesh& m) {
  const size_t n = m.positions.size(), width = std::min<size_t>(256, n);
  std::vector<std::vector<glm::dvec3>> blocks(((n + width - 1) / width / 4 + 1) * (width / 4 + 1));
  for (size_t i = 0; i < n; ++i) blocks[(i / width / 4) * (width / 4 + 1) + (i % width) / 4].push_back(m.positions[i]);
  double sum = 0.0;
  for (const auto& b : blocks) {
    const glm::dvec3 c = std::accumulate(b.begin(), b.end(), glm::dvec3(0.0)) / double(std::max<size_t>(b.size(), 1));
    for (const auto& p : b) sum += glm::length(p - c);
  }
  return sum / double(n);
}

}  // namespace

TEST(MeshVertexOrder, ArmchairKeepsItsSurfaceAndItsBlocksHoldNearbyVertices) {
  const Scene given = load_scene_named("showroom", WEFT_SOURCE_ASSETS);
  const Scene ordered = order_scene_meshes(given);
  ASSERT_EQ(ordered.objects.size(), given.objects.size());
  size_t cloth = 0;
  for (size_t i = 0; i < given.objects.size(); ++i) {
    const TriangleMesh &g = given.objects[i].mesh, &o = ordered.objects[i].mesh;
    EXPECT_EQ(ordered.objects[i].name, given.objects[i].name);
    expect_same_surface(g, o, given.objects[i].name);
    if (!given.objects[i].is_cloth() || g.positions.size() < 1024) continue;
    ++cloth;
    const double before = block_spread(g), after = block_spread(o);
    std::printf("%s: %zu vertices, mean distance to the block's centroid %.4f -> %.4f\n", given.objects[i].name.c_str(),
                g.positions.size(), before, after);
    EXPECT_LT(after, 0.5 * before) << given.objects[i].name;
  }
  EXPECT_GT(cloth, 0u) << "the armchair should have cloth meshes of several blocks";
}

TEST(MeshVertexOrder, PartialRowsAndBlocksStillGiveAPermutation) {
  for (const auto& [nu, nv] : {std::pair{2, 3}, {15, 16}, {37, 29}, {255, 5}, {63, 64}}) {
    TriangleMesh given = parametric_grid(nu, nv, [](double u, double v) {
      return glm::dvec3(std::cos(3 * u), std::sin(3 * u), 2 * v);  // a curved sheet: no order by accident
    });
    finish_mesh(given, true, "grid");
    const std::vector<uint32_t> order = spatial_vertex_order(given);
    std::vector<uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<uint32_t> all(given.positions.size());
    std::iota(all.begin(), all.end(), 0u);
    EXPECT_EQ(sorted, all) << nu << "x" << nv;
    TriangleMesh ordered = given;
    order_vertices_spatially(ordered);
    expect_same_surface(given, ordered, "grid " + std::to_string(nu) + "x" + std::to_string(nv));
  }
}

TEST(MeshVertexOrder, EmptyAttributesStayEmptyAndBadPermutationsAreRefused) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.triangles = {{0, 1, 2}, {2, 1, 3}};
  TriangleMesh p = m;
  const std::vector<uint32_t> reverse = {3, 2, 1, 0};
  permute_vertices(p, reverse);
  EXPECT_TRUE(p.normals.empty() && p.uvs.empty() && p.warps.empty());
  EXPECT_EQ(p.positions[3], m.positions[0]);
  EXPECT_EQ(p.triangles[0], (std::array<uint32_t, 3>{3, 2, 1}));
  const std::vector<uint32_t> repeated = {0, 0, 1, 2}, short_ = {0, 1, 2};
  EXPECT_THROW(permute_vertices(p, repeated), std::invalid_argument);
  EXPECT_THROW(permute_vertices(p, short_), std::invalid_argument);
}
