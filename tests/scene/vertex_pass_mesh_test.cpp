// The per-vertex passes' vertices on dense meshes (scene/vertex_pass_mesh.h), against what a
// blend of a coarse triangle's corners must do whatever the simplifier chose:
//  - a small mesh keeps every vertex;
//  - a dense flat sheet keeps a few of its vertices, every mesh vertex lies on its pass triangle
//    (the blended position is its own) and a linear function of position blends exactly;
//  - a dense sphere: the blended normals, recomputed here, are within the budget asked for, and a
//    tighter budget keeps more vertices;
//  - a thin two-sided sheet: each side's vertices blend their own side's corners only;
//  - an edge bound keeps 95 % of the pass's edges within 1.5 times it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/procedural_meshes.h"
#include "scene/vertex_pass_mesh.h"

using namespace weft;

namespace {

TriangleMesh sheet(int n, double z = 0.0, bool up = true) {
  TriangleMesh m = parametric_grid(n, n, [&](double s, double t) { return glm::dvec3(s, t, z); });
  finish_mesh(m, true, "sheet");
  for (auto& nn : m.normals) nn = glm::dvec3(0, 0, up ? 1 : -1);
  return m;
}

TriangleMesh sphere(int n) {
  TriangleMesh m = parametric_grid(n, n, [](double s, double t) {
    const double phi = 2.0 * M_PI * s, theta = 0.05 + (M_PI - 0.1) * t;  // poles cut: no collapsed rows
    return 0.3 * glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  });
  finish_mesh(m, true, "sphere");
  for (size_t i = 0; i < m.positions.size(); ++i) {
    m.normals[i] = glm::normalize(m.positions[i]);
    const glm::dvec3 around(-m.positions[i].y, m.positions[i].x, 0.0);
    m.warps[i] = glm::normalize(around);
  }
  return m;
}

void expect_valid(const VertexPassMesh& p, const TriangleMesh& m) {
  ASSERT_FALSE(p.whole());
  ASSERT_EQ(p.corners.size(), m.positions.size());
  ASSERT_TRUE(std::is_sorted(p.vertices.begin(), p.vertices.end()));
  for (size_t v = 0; v < m.positions.size(); ++v) {
    for (uint32_t c : p.corners[v]) ASSERT_LT(c, p.vertices.size());
    const glm::vec3 w = p.weights[v];
    EXPECT_NEAR(w.x + w.y + w.z, 1.0, 1e-5);
    EXPECT_GE(std::min({w.x, w.y, w.z}), -1e-6f);
  }
}

double angle_deg(glm::dvec3 a, glm::dvec3 b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

}  // namespace

TEST(VertexPassMesh, SmallMeshKeepsEveryVertex) {
  const TriangleMesh m = sheet(20);
  ASSERT_LT(m.positions.size(), VertexPassMeshOptions::kKeepAllVertices);
  EXPECT_TRUE(vertex_pass_mesh(m).whole());
  const std::vector<glm::dvec3> values = {{1, 2, 3}, {4, 5, 6}};
  EXPECT_EQ(blend_pass_values(VertexPassMesh{}, values), values);
}

TEST(VertexPassMesh, FlatSheetBlendsPositionsAndLinearValuesExactly) {
  const TriangleMesh m = sheet(120);  // 14 641 vertices
  const VertexPassMesh p = vertex_pass_mesh(m);
  expect_valid(p, m);
  EXPECT_LT(p.vertices.size(), m.positions.size() / 10);
  std::vector<glm::dvec3> pos, linear;
  for (uint32_t v : p.vertices) {
    pos.push_back(m.positions[v]);
    linear.push_back(glm::dvec3(2.0 * m.positions[v].x - m.positions[v].y + 0.5));
  }
  const auto blended = blend_pass_values(p, pos), blended_linear = blend_pass_values(p, linear);
  for (size_t v = 0; v < m.positions.size(); ++v) {
    EXPECT_NEAR(glm::length(blended[v] - m.positions[v]), 0.0, 1e-5) << v;
    EXPECT_NEAR(blended_linear[v].x, 2.0 * m.positions[v].x - m.positions[v].y + 0.5, 1e-5) << v;
  }
}

TEST(VertexPassMesh, SphereKeepsTheNormalBudgetAndTighterKeepsMore) {
  const TriangleMesh m = sphere(100);
  VertexPassMeshOptions loose;
  const VertexPassMesh p = vertex_pass_mesh(m, loose);
  expect_valid(p, m);
  std::vector<glm::dvec3> normals;
  for (uint32_t v : p.vertices) normals.push_back(m.normals[v]);
  const auto blended = blend_pass_values(p, normals);
  std::vector<double> err;
  for (size_t v = 0; v < m.positions.size(); ++v) err.push_back(angle_deg(blended[v], m.normals[v]));
  std::sort(err.begin(), err.end());
  EXPECT_LE(err[err.size() * 95 / 100], loose.normal_p95_deg + 1e-6);
  EXPECT_LE(err[err.size() * 99 / 100], loose.normal_p99_deg + 1e-6);
  EXPECT_NEAR(err[err.size() * 95 / 100], p.normal_p95_deg, 0.05);
  VertexPassMeshOptions tight = loose;
  tight.warp_p95_deg = 1.5;
  const VertexPassMesh q = vertex_pass_mesh(m, tight);
  const size_t kept_tight = q.whole() ? m.positions.size() : q.vertices.size();
  EXPECT_GT(kept_tight, p.vertices.size());
}

TEST(VertexPassMesh, ThinTwoSidedSheetBlendsItsOwnSide) {
  TriangleMesh top = sheet(80, 0.001, true), bottom = sheet(80, 0.0, false);
  TriangleMesh m = top;
  const uint32_t base = uint32_t(m.positions.size());
  m.positions.insert(m.positions.end(), bottom.positions.begin(), bottom.positions.end());
  m.normals.insert(m.normals.end(), bottom.normals.begin(), bottom.normals.end());
  m.warps.insert(m.warps.end(), bottom.warps.begin(), bottom.warps.end());
  m.uvs.insert(m.uvs.end(), bottom.uvs.begin(), bottom.uvs.end());
  for (auto t : bottom.triangles) m.triangles.push_back({t[0] + base, t[2] + base, t[1] + base});
  const VertexPassMesh p = vertex_pass_mesh(m);
  expect_valid(p, m);
  for (size_t v = 0; v < m.positions.size(); ++v)
    for (uint32_t c : p.corners[v]) EXPECT_GT(glm::dot(m.normals[p.vertices[c]], m.normals[v]), 0.0) << v;
}

TEST(VertexPassMesh, EdgeBoundIsKept) {
  const TriangleMesh m = sheet(120);
  VertexPassMeshOptions o;
  o.max_edge = 0.05;  // of a 1 m sheet
  const VertexPassMesh p = vertex_pass_mesh(m, o);
  ASSERT_FALSE(p.whole());
  EXPECT_LE(p.edge_p95, 1.5 * 0.05);
  EXPECT_GT(p.vertices.size(), vertex_pass_mesh(m).vertices.size());
}
