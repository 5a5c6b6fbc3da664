// Midpoint refinement (scene/mesh_subdivision.h): counts by closed form on a grid and a closed
// solid, every shared edge split once (V' = V + E, no crack: boundary edges double, interior
// edges stay shared by two triangles), each new vertex's attributes at its edge's midpoint, the
// surface and UV areas unchanged, the winding kept; the bundled armchair glTF and a Khronos
// sample refine the same way.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "scene/mesh_subdivision.h"
#include "scene/scene_file.h"

using namespace weft;
using glm::dvec2;
using glm::dvec3;

namespace {

using Edge = std::pair<uint32_t, uint32_t>;

// Triangles per undirected edge (by indices).
std::map<Edge, int> edge_uses(const TriangleMesh& m) {
  std::map<Edge, int> uses;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  return uses;
}
size_t boundary_edges(const TriangleMesh& m) {
  size_t n = 0;
  for (const auto& [e, uses] : edge_uses(m)) n += uses == 1;
  return n;
}

dvec3 cross_of(const TriangleMesh& m, const std::array<uint32_t, 3>& t) {
  return glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
}
double area(const TriangleMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles) a += 0.5 * glm::length(cross_of(m, t));
  return a;
}
double uv_area(const TriangleMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles) {
    const dvec2 e1 = m.uvs[t[1]] - m.uvs[t[0]], e2 = m.uvs[t[2]] - m.uvs[t[0]];
    a += 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
  }
  return a;
}

// An n×n-cell grid on a curved sheet z = 0.3·sin(x)·cos(y), two triangles per cell, with UVs
// (u = x), finished as a cloth mesh (normals, warps).
TriangleMesh grid(int n) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      m.positions.push_back({x, y, 0.3 * std::sin(3 * x) * std::cos(2 * y)});
      m.uvs.push_back({x, y});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  finish_mesh(m, true, "grid");
  return m;
}

// A closed octahedron (no UVs), outward winding.
TriangleMesh octahedron() {
  TriangleMesh m;
  m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  finish_mesh(m, false, "octahedron");
  return m;
}

// Everything a refinement must keep, checked against the mesh it came from.
void expect_refines(const TriangleMesh& m, const TriangleMesh& r, const std::string& what) {
  const auto uses = edge_uses(m);
  ASSERT_EQ(r.positions.size(), m.positions.size() + uses.size()) << what << ": V' = V + E";
  ASSERT_EQ(r.triangles.size(), 4 * m.triangles.size()) << what;
  ASSERT_EQ(r.normals.size(), r.positions.size()) << what;
  ASSERT_EQ(r.uvs.size(), m.uvs.empty() ? 0 : r.positions.size()) << what;
  ASSERT_EQ(r.warps.size(), m.warps.empty() ? 0 : r.positions.size()) << what;
  EXPECT_NEAR(area(r), area(m), 1e-12 * area(m)) << what;
  if (!m.uvs.empty()) { EXPECT_NEAR(uv_area(r), uv_area(m), 1e-12 * uv_area(m)) << what; }
  // Interior edges stay shared by exactly two triangles, boundary edges split into two each.
  EXPECT_EQ(boundary_edges(r), 2 * boundary_edges(m)) << what;
  int most = 0;  // triangles on one edge (2 on a manifold; more where a glTF joins more)
  for (const auto& [e, n] : uses) most = std::max(most, n);
  for (const auto& [e, n] : edge_uses(r)) ASSERT_LE(n, most) << what;
  // The original vertices keep index and values.
  for (size_t i = 0; i < m.positions.size(); ++i) {
    ASSERT_EQ(r.positions[i], m.positions[i]) << what;
    ASSERT_EQ(r.normals[i], m.normals[i]) << what;
    if (!m.warps.empty()) { ASSERT_EQ(r.warps[i], m.warps[i]) << what; }
  }
  // Each edge's new vertex: the first triangle using the edge names it (child 0 holds corner
  // a, ab, ca); its attributes are the edge's midpoint values.
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& p = m.triangles[t];
    const auto& c0 = r.triangles[4 * t];
    const auto& c1 = r.triangles[4 * t + 1];
    ASSERT_EQ(c0[0], p[0]) << what;
    ASSERT_EQ(c1[1], p[1]) << what;
    const uint32_t mids[3] = {c0[1], c1[2], c0[2]};  // ab, bc, ca
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = p[k], b = p[(k + 1) % 3], v = mids[k];
      ASSERT_GE(v, m.positions.size()) << what;
      EXPECT_EQ(r.positions[v], 0.5 * (m.positions[a] + m.positions[b])) << what;
      const dvec3 n = glm::normalize(m.normals[a] + m.normals[b]);
      EXPECT_NEAR(glm::length(r.normals[v] - n), 0.0, 1e-15) << what;
      if (!m.uvs.empty()) { EXPECT_EQ(r.uvs[v], 0.5 * (m.uvs[a] + m.uvs[b])) << what; }
      if (!m.warps.empty()) {
        const dvec3 w = 0.5 * (m.warps[a] + m.warps[b]);
        const dvec3 t = w - glm::dot(w, n) * n;
        EXPECT_NEAR(glm::length(r.warps[v]), 1.0, 1e-12) << what;
        EXPECT_NEAR(glm::dot(r.warps[v], r.normals[v]), 0.0, 1e-12) << what;
        // Where the mean warp lies along the normal (fixed tangents of an uv-less solid) any
        // tangent frames the vertex; elsewhere it is the mean made ⟂ n.
        if (glm::length(t) > 1e-9) { EXPECT_NEAR(glm::length(r.warps[v] - glm::normalize(t)), 0.0, 1e-12) << what; }
      }
    }
    // Winding: every child faces the parent's way.
    const dvec3 parent = cross_of(m, p);
    for (int c = 0; c < 4; ++c) EXPECT_GT(glm::dot(cross_of(r, r.triangles[4 * t + c]), parent), 0.0) << what;
  }
}

}  // namespace

TEST(MeshSubdivision, GridCountsFollowTheClosedForm) {
  for (int n : {1, 3, 7}) {
    const TriangleMesh m = grid(n);
    for (int level = 0; level <= 2; ++level) {
      const TriangleMesh r = subdivide_midpoint(m, level);
      const int s = n << level;  // cells per side
      EXPECT_EQ(r.positions.size(), size_t((s + 1) * (s + 1))) << "n " << n << " level " << level;
      EXPECT_EQ(r.triangles.size(), size_t(2 * s * s)) << "n " << n << " level " << level;
      // No vertex twice: the refined grid's points are the (s+1)² distinct lattice points.
      std::set<std::pair<double, double>> uv;
      for (const dvec2& t : r.uvs) uv.insert({t.x, t.y});
      EXPECT_EQ(uv.size(), r.positions.size()) << "n " << n << " level " << level;
      for (const dvec2& t : r.uvs) {
        EXPECT_NEAR(t.x * s, std::round(t.x * s), 1e-9);
        EXPECT_NEAR(t.y * s, std::round(t.y * s), 1e-9);
      }
    }
  }
}

TEST(MeshSubdivision, GridKeepsAreaAttributesAndSharedEdges) {
  const TriangleMesh m = grid(5);
  expect_refines(m, subdivide_midpoint(m), "grid");
  const TriangleMesh r1 = subdivide_midpoint(m);
  expect_refines(r1, subdivide_midpoint(r1), "grid level 2");
}

TEST(MeshSubdivision, ClosedSolidStaysClosed) {
  const TriangleMesh m = octahedron();
  TriangleMesh r = m;
  for (int level = 1; level <= 3; ++level) {
    const TriangleMesh next = subdivide_midpoint(r);
    expect_refines(r, next, "octahedron level " + std::to_string(level));
    r = next;
    const auto uses = edge_uses(r);
    for (const auto& [e, n] : uses) ASSERT_EQ(n, 2) << "level " << level << ": not watertight";
    // Euler: V − E + F = 2; F = 8·4^level, E = 3F/2, so V = 2 + F/2.
    const size_t f = 8u << (2 * level);
    EXPECT_EQ(r.triangles.size(), f);
    EXPECT_EQ(uses.size(), 3 * f / 2);
    EXPECT_EQ(r.positions.size(), 2 + f / 2);
  }
  // Warps stay unit and ⟂ the normal everywhere, and the mesh passes its own checks.
  for (size_t i = 0; i < r.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(r.warps[i]), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(r.warps[i], r.normals[i]), 0.0, 1e-12);
  }
  EXPECT_EQ(repair_mesh(r, false, "refined octahedron").degenerate_triangles_dropped, 0u);
}

TEST(MeshSubdivision, LevelsAndMissingAttributes) {
  TriangleMesh bare;
  bare.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  bare.triangles = {{0, 1, 2}};
  const TriangleMesh r = subdivide_midpoint(bare, 2);
  EXPECT_EQ(r.positions.size(), 15u);  // a triangle of side 4: (4+1)(4+2)/2
  EXPECT_EQ(r.triangles.size(), 16u);
  EXPECT_TRUE(r.normals.empty());
  EXPECT_TRUE(r.uvs.empty());
  EXPECT_TRUE(r.warps.empty());
  EXPECT_EQ(subdivide_midpoint(bare, 0).positions, bare.positions);
  EXPECT_THROW(subdivide_midpoint(bare, -1), std::invalid_argument);
  bare.normals = {{0, 0, 1}};
  EXPECT_THROW(subdivide_midpoint(bare), std::invalid_argument);
}

TEST(MeshSubdivision, ArmchairGltfRefinesItsClothOnly) {
  const Scene s = load_scene_named(std::string(WEFT_SOURCE_ASSETS) + "/scenes/armchair.gltf", WEFT_SOURCE_ASSETS);
  const Scene r = refine_cloth_meshes(s, 1);
  ASSERT_EQ(r.objects.size(), s.objects.size());
  size_t cloth = 0;
  for (size_t i = 0; i < s.objects.size(); ++i) {
    const SceneObject &o = s.objects[i], &q = r.objects[i];
    if (o.material != Material::cloth) {
      EXPECT_EQ(q.mesh.positions, o.mesh.positions) << o.name;
      EXPECT_EQ(q.mesh.triangles, o.mesh.triangles) << o.name;
      continue;
    }
    ++cloth;
    expect_refines(o.mesh, q.mesh, o.name);
    TriangleMesh copy = q.mesh;
    EXPECT_EQ(repair_mesh(copy, true, o.name).degenerate_triangles_dropped, 0u) << o.name;
  }
  EXPECT_EQ(cloth, 2u);
}

TEST(MeshSubdivision, KhronosSampleRefines) {
  const std::filesystem::path file = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " absent (apt-get install assimp-testmodels)";
  const Scene s = load_scene_named(file.string(), WEFT_SOURCE_ASSETS, "linen_plain");
  ASSERT_FALSE(s.objects.empty());
  for (const SceneObject& o : s.objects) {
    ASSERT_EQ(o.material, Material::cloth) << o.name;
    const TriangleMesh r = subdivide_midpoint(o.mesh, 2);
    expect_refines(subdivide_midpoint(o.mesh), r, o.name);
    EXPECT_EQ(r.triangles.size(), 16 * o.mesh.triangles.size());
    EXPECT_NEAR(area(r), area(o.mesh), 1e-12 * area(o.mesh)) << o.name;
    // The box's faces are UV islands of their own (split vertices along the cube's edges):
    // their seams stay open exactly as they were, every seam edge split in two.
    EXPECT_EQ(boundary_edges(r), 4 * boundary_edges(o.mesh)) << o.name;
  }
}
