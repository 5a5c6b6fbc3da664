// Where the weave layer can show anything (methods/weave/weave_reach.h): its estimate of the finest
// thread footprint in view against the footprint measured pixel by pixel, from the rays through
// neighbouring pixels onto a swatch with stretched UVs, seen square, grazing and off centre: never
// above the finest footprint any pixel shows (the layer never skips what it would draw) and close
// to it (it skips what it cannot draw); nothing in view is infinity; the orbit's bound is below
// every camera's on the orbit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "methods/weave/weave_reach.h"
#include "scene/procedural_meshes.h"

using namespace weft;
using glm::dvec2;
using glm::dvec3;

namespace {
constexpr int kW = 160, kH = 120, kRows = 5;
const dvec2 kTilesPerUv{20.0, 20.0};

// Each vertex's weave coordinates: its UV times kTilesPerUv (an object's authored repeats per UV unit).
std::vector<dvec2> tiled(const TriangleMesh& m) {
  std::vector<dvec2> st;
  for (const dvec2& uv : m.uvs) st.push_back(uv * kTilesPerUv);
  return st;
}

// A 1 m swatch at z = 0 whose u is stretched 3× (a repeat three times finer along x).
TriangleMesh stretched_swatch() {
  TriangleMesh m = swatch_mesh(1.0, 16);
  for (auto& uv : m.uvs) uv.x *= 3.0;
  return m;
}

// The finest footprint in threads any pixel of the swatch shows (weave_layer.frag's: the longer of
// its two tile-space steps to the next pixel), infinity where none shows it.
double measured_footprint(const Camera& camera) {
  auto st_at = [&](double px, double py, dvec2& st) {
    const dvec3 d = camera_ray(camera, kW, kH, px, py);
    if (d.z >= 0.0) return false;
    const dvec3 p = camera.position - (camera.position.z / d.z) * d;
    if (std::abs(p.x) > 0.5 || std::abs(p.y) > 0.5) return false;
    st = dvec2(3.0 * (p.x + 0.5), p.y + 0.5) * kTilesPerUv;
    return true;
  };
  double best = std::numeric_limits<double>::infinity();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      dvec2 s, sx, sy;
      if (!st_at(x + 0.5, y + 0.5, s) || !st_at(x + 1.5, y + 0.5, sx) || !st_at(x + 0.5, y + 1.5, sy)) continue;
      best = std::min(best, std::max(glm::length(sx - s), glm::length(sy - s)) * kRows);
    }
  return best;
}
}  // namespace

TEST(WeaveReach, BoundsTheFootprintPixelsShow) {
  const TriangleMesh mesh = stretched_swatch();
  const WeaveReach reach(mesh, tiled(mesh), kRows);
  struct Case {
    const char* name;
    dvec3 eye, target, up;
  };
  for (const Case& c : {Case{"square, near", {0.0, 0.0, 0.3}, {0.0, 0.0, 0.0}, {0, 1, 0}},
                        Case{"square, far", {0.1, 0.0, 4.0}, {0.1, 0.0, 0.0}, {0, 1, 0}},
                        Case{"grazing", {0.0, -0.9, 0.15}, {0.0, 0.1, 0.0}, {0, 0, 1}},
                        Case{"oblique, off centre", {0.7, -0.6, 0.5}, {0.2, 0.0, 0.0}, {0, 0, 1}}}) {
    SCOPED_TRACE(c.name);
    Camera camera;
    camera.position = c.eye, camera.target = c.target, camera.up = c.up;
    camera.fov_deg = 40.0;
    const double measured = measured_footprint(camera);
    ASSERT_TRUE(std::isfinite(measured));
    const double bound = reach.nearest_footprint(weave_view(camera, kW, kH));
    std::cout << c.name << ": estimate " << bound << " threads a pixel, finest shown " << measured << "\n";
    EXPECT_LE(bound, measured);
    EXPECT_GT(bound, 0.6 * measured);  // 6 cm triangles: the nearest point of a vertex's triangles
  }
}

TEST(WeaveReach, NothingInViewIsOutOfReach) {
  const TriangleMesh mesh = stretched_swatch();
  const WeaveReach reach(mesh, tiled(mesh), kRows);
  Camera away;
  away.position = {0.0, 0.0, 0.3}, away.target = {0.0, 0.0, 1.0}, away.up = {0, 1, 0};
  EXPECT_TRUE(std::isinf(reach.nearest_footprint(weave_view(away, kW, kH))));
}

TEST(WeaveReach, TheOrbitBoundsEveryCameraOnIt) {
  const TriangleMesh mesh = stretched_swatch();
  const WeaveReach reach(mesh, tiled(mesh), kRows);
  Camera camera;
  camera.position = {0.9, -1.2, 0.6}, camera.target = {0.0, 0.0, 0.0};
  const dvec3 pivot{0.3, 0.1, 0.0};
  const double pixel = weave_view(camera, kW, kH).corner_pixel;
  const double orbit = reach.nearest_footprint_orbiting(camera.position, pivot, pixel);
  double finest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 72; ++i) {
    const double turn = glm::radians(5.0 * i);
    Camera c = camera;
    const dvec3 r = c.position - pivot;
    c.position = pivot + dvec3(r.x * std::cos(turn) - r.y * std::sin(turn), r.x * std::sin(turn) + r.y * std::cos(turn), r.z);
    c.target = pivot;
    finest = std::min(finest, reach.nearest_footprint(weave_view(c, kW, kH)));
  }
  EXPECT_LE(orbit, finest);
  EXPECT_GT(orbit, 0.3 * finest);
}

TEST(WeaveReach, CollapsedUvsAreAlwaysInReachAndLooseVerticesNever) {
  TriangleMesh mesh = stretched_swatch();
  for (auto& uv : mesh.uvs) uv = dvec2(0.5);  // every triangle's UVs one point: the layer's footprint is 0
  mesh.positions.push_back({5.0, 5.0, 5.0});  // a vertex in no triangle
  mesh.uvs.push_back({0.0, 0.0});
  const WeaveReach reach(mesh, tiled(mesh), kRows);
  EXPECT_EQ(reach.vertices().front().threads_per_metre, 0.0f);
  EXPECT_TRUE(std::isinf(reach.vertices().back().threads_per_metre));
  Camera far;
  far.position = {0.0, 0.0, 50.0}, far.target = {0.0, 0.0, 0.0}, far.up = {0, 1, 0};
  EXPECT_EQ(reach.nearest_footprint(weave_view(far, kW, kH)), 0.0);
}
