// Benchmark (label bench): how many of the per-vertex passes' 4×4 texel blocks (llvmpipe's unit of
// fragment work) hold a vertex the frame shows, for the showroom's cloth in four vertex orders:
// the scene's (the glTF's), a plain Morton order (meshoptimizer's spatial sort), the Morton order laid out block
// by block ("M.blocks"), and the bake's (grouped by facing first, scene/mesh_vertex_order.h). Visible: a vertex of a triangle that
// a ray through some pixel centre of a 640×480 frame hits first (Embree; the GL's marks add the
// silhouette's ties), from the scene's camera turned about the product (kiosk/turntable.h).
// WEFT_VERTEX_BLOCK_SCENE: the scene (default "showroom"); WEFT_VERTEX_BLOCK_BUNDLE: a baked bundle's
// scene instead, its stored order in the column "given" (a bundle baked with the order shows the
// bake's column there).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <set>
#include <vector>

#include <meshoptimizer.h>

#include "bundle/bundle_reader.h"
#include "kiosk/turntable.h"
#include "runtime/scene_bundle.h"
#include "reference/ray_scene.h"
#include "scene/mesh_vertex_order.h"
#include "scene/scene_file.h"

using namespace weft;

namespace {

constexpr int kWidth = 640, kHeight = 480;

// Blocks holding a vertex whose index `place` gives is visible, out of the blocks holding any.
std::pair<size_t, size_t> blocks(const std::vector<bool>& visible, const std::vector<uint32_t>& place) {
  const size_t n = visible.size(), width = std::min<size_t>(kVertexTexelRow, n);
  auto block = [&](size_t i) { return std::pair{i / width / kVertexTexelBlock, i % width / kVertexTexelBlock}; };
  std::set<std::pair<size_t, size_t>> shown, all;
  for (size_t v = 0; v < n; ++v) {
    all.insert(block(v));
    if (visible[v]) shown.insert(block(place[v]));
  }
  return {shown.size(), all.size()};
}

std::vector<uint32_t> morton(const TriangleMesh& m) {
  std::vector<float> xyz;
  for (const auto& p : m.positions) xyz.insert(xyz.end(), {float(p.x), float(p.y), float(p.z)});
  std::vector<uint32_t> rank(m.positions.size());
  meshopt_spatialSortRemap(rank.data(), xyz.data(), rank.size(), sizeof(float) * 3);
  return rank;
}

}  // namespace

TEST(VertexBlockBench, VisibleBlocksPerVertexOrder) {
  const char* name = std::getenv("WEFT_VERTEX_BLOCK_SCENE");
  const char* bundle = std::getenv("WEFT_VERTEX_BLOCK_BUNDLE");
  const Scene scene = bundle && *bundle ? read_scene_bundle(bundle::BundleReader::open(bundle)).scene
                                        : load_scene_named(name && *name ? name : "showroom", WEFT_SOURCE_ASSETS);
  const RayScene rays(scene);
  const glm::dvec3 pivot = turntable_pivot(scene);
  std::printf("%-6s %-18s %8s %8s %8s %8s %9s %8s\n", "turn", "object", "vertices", "visible", "given", "Morton",
              "M.blocks", "bake");
  for (double deg : {0.0, 5.0, 90.0, 180.0, 270.0}) {
    const Camera cam = turned_about_z(scene.camera, deg, pivot);
    std::vector<std::vector<bool>> visible(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) visible[i].assign(scene.objects[i].mesh.positions.size(), false);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        if (const auto hit = rays.intersect(cam.position, camera_ray(cam, kWidth, kHeight, x + 0.5, y + 0.5)))
          for (uint32_t v : scene.objects[hit->object].mesh.triangles[hit->triangle]) visible[hit->object][v] = true;
    std::array<size_t, 4> shown{}, total{};
    size_t vertices = 0, seen = 0;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
      const TriangleMesh& m = scene.objects[i].mesh;
      if (!scene.objects[i].is_cloth() || m.positions.empty()) continue;
      std::vector<uint32_t> identity(m.positions.size());
      for (size_t v = 0; v < identity.size(); ++v) identity[v] = uint32_t(v);
      TriangleMesh unfaced = m;  // no normals: one group, the Morton order alone in blocks
      unfaced.normals.clear();
      const std::vector<uint32_t> orders[4] = {identity, morton(m), spatial_vertex_order(unfaced),
                                               spatial_vertex_order(m)};
      std::array<double, 4> fraction{};
      for (int k = 0; k < 4; ++k) {
        const auto [s, t] = blocks(visible[i], orders[k]);
        shown[k] += s, total[k] += t, fraction[k] = double(s) / double(t);
      }
      const size_t n = std::count(visible[i].begin(), visible[i].end(), true);
      vertices += m.positions.size(), seen += n;
      std::printf("%-6.0f %-18s %8zu %7.1f%% %7.1f%% %7.1f%% %8.1f%% %7.1f%%\n", deg, scene.objects[i].name.c_str(),
                  m.positions.size(), 100.0 * n / m.positions.size(), 100 * fraction[0], 100 * fraction[1],
                  100 * fraction[2], 100 * fraction[3]);
    }
    std::printf("%-6.0f %-18s %8zu %7.1f%% %7.1f%% %7.1f%% %8.1f%% %7.1f%%\n", deg, "(all cloth)", vertices,
                100.0 * seen / vertices, 100.0 * shown[0] / total[0], 100.0 * shown[1] / total[1],
                100.0 * shown[2] / total[2], 100.0 * shown[3] / total[3]);
    EXPECT_LE(shown[3], shown[0]);
  }
}
