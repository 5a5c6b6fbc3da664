// A closed part's outside (scene/mesh_orientation.h), against what a cube is known to be: its
// outward winding encloses +1 m³ and its normals point away from its centre. Turned inside out
// (winding, normals, or both) it is found out and turned back; a cube split at every face's edge
// (a UV seam per face) is still closed; an open box and a sheet are left alone.
#include <gtest/gtest.h>

#include <array>

#include "scene/mesh_orientation.h"

using namespace weft;

namespace {

// A unit cube, four vertices per face (each face its own UV island, as an exporter writes it),
// wound outward (counter-clockwise seen from outside), normals along each face's outward axis.
TriangleMesh cube(bool with_top = true) {
  TriangleMesh m;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      if (!with_top && axis == 2 && side > 0) continue;
      glm::dvec3 n(0.0);
      n[axis] = side;
      const glm::dvec3 u = glm::dvec3(n.y, n.z, n.x), v = glm::cross(n, u);  // u × v = n
      const uint32_t base = uint32_t(m.positions.size());
      for (auto [a, b] : std::array<std::pair<double, double>, 4>{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}) {
        m.positions.push_back(0.5 * (n + a * u + b * v));
        m.normals.push_back(n);
      }
      m.triangles.push_back({base, base + 1, base + 2});
      m.triangles.push_back({base, base + 2, base + 3});
    }
  return m;
}

double volume(const TriangleMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) v += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
  return v;
}

}  // namespace

TEST(MeshOrientation, AnOutwardCubeIsClosedAndLeftAlone) {
  const TriangleMesh m = cube();
  ASSERT_NEAR(volume(m), 1.0, 1e-12);  // the fixture itself: outward
  const MeshOrientation o = mesh_orientation(m);
  EXPECT_TRUE(o.closed);
  EXPECT_FALSE(o.winding_inward);
  EXPECT_FALSE(o.normals_inward);
}

TEST(MeshOrientation, AnInsideOutCubeIsTurnedBack) {
  for (const bool flip_winding : {false, true})
    for (const bool flip_normals : {false, true}) {
      if (!flip_winding && !flip_normals) continue;
      TriangleMesh m = cube();
      if (flip_winding)
        for (auto& t : m.triangles) std::swap(t[1], t[2]);
      if (flip_normals)
        for (auto& n : m.normals) n = -n;
      const MeshOrientation o = mesh_orientation(m);
      EXPECT_TRUE(o.closed);
      EXPECT_EQ(o.winding_inward, flip_winding);
      EXPECT_EQ(o.normals_inward, flip_normals);
      turn_outward(m.triangles, m.normals, o);
      EXPECT_NEAR(volume(m), 1.0, 1e-12) << flip_winding << flip_normals;
      for (size_t v = 0; v < m.positions.size(); ++v)
        EXPECT_GT(glm::dot(m.normals[v], m.positions[v]), 0.0) << "vertex " << v;
    }
}

TEST(MeshOrientation, OpenPartsHaveNoInside) {
  TriangleMesh open = cube(false);
  for (auto& t : open.triangles) std::swap(t[1], t[2]);
  EXPECT_FALSE(mesh_orientation(open).closed);
  TriangleMesh sheet;
  sheet.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  sheet.normals.assign(6, glm::dvec3(0, 0, -1));
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  const MeshOrientation o = mesh_orientation(sheet);
  EXPECT_FALSE(o.closed);
  EXPECT_FALSE(o.inward());
}
