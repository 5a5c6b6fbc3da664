// `weft bake --subdivide N` end to end: the bundle's cloth meshes are the scene's refined N
// levels (scene/mesh_subdivision.h; floors and occluders unrefined), in the bake's vertex
// order (scene/mesh_vertex_order.h), with the weighting-table
// sections sized for them; a level outside 0..kMaxSubdivision is bad usage (exit 2).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "bake/selection/scene_selection.h"
#include "bundle/bundle_reader.h"
#include "runtime/shading_data.h"
#include "runtime/scene_bundle.h"
#include "scene/mesh_subdivision.h"
#include "scene/mesh_vertex_order.h"
#include "scene/scene_file.h"

namespace fs = std::filesystem;
using namespace weft;

namespace {

int bake(const std::string& args) {
  const std::string cmd = "WEFT_ASSETS=" WEFT_SOURCE_ASSETS " " + std::string(WEFT_BINARY) + " bake " + args +
                          " >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("weft_bake_subdivide_" + name); }

}  // namespace

TEST(BakeSubdivide, BundleHoldsTheRefinedClothMeshes) {
  const fs::path out = temp("pillow.weftbundle");
  // Tiny tables (grid 4, 2 levels, 1+1 samples) and 8² SDFs: only the meshes and the sections'
  // sizes matter. The pillow is occluded (by itself and the floor): visibility per vertex.
  ASSERT_EQ(bake("--scene pillow --subdivide 1 --table-grid 4 --lambda-levels 2 --tangent-samples 1 1 --sdf-resolution 8 "
                 "--floor-sdf-resolution 8 --out " + out.string()),
            0);
  // The bake orders the scene's vertices, then refines the cloth and orders it anew.
  const Scene given = order_scene_meshes(load_scene_named("pillow", WEFT_SOURCE_ASSETS));
  const Scene expected = refine_and_order_meshes(given, 1);
  const auto reader = bundle::BundleReader::open(out);
  const SceneBundle b = read_scene_bundle(reader);
  ASSERT_EQ(b.scene.objects.size(), expected.objects.size());
  for (size_t i = 0; i < expected.objects.size(); ++i) {
    const TriangleMesh &m = b.scene.objects[i].mesh, &e = expected.objects[i].mesh;
    ASSERT_EQ(m.positions.size(), e.positions.size()) << b.scene.objects[i].name;
    ASSERT_EQ(m.triangles, e.triangles) << b.scene.objects[i].name;
    for (size_t v = 0; v < e.positions.size(); ++v) {
      ASSERT_NEAR(glm::length(m.positions[v] - e.positions[v]), 0.0, 1e-6);  // stored as f32
      ASSERT_NEAR(glm::length(m.warps[v] - e.warps[v]), 0.0, 1e-6);
    }
    if (given.objects[i].material == Material::cloth)
      EXPECT_EQ(m.triangles.size(), 4 * given.objects[i].mesh.triangles.size());
    else
      EXPECT_EQ(m.triangles, given.objects[i].mesh.triangles);
  }
  // Visibility coefficients for every refined vertex (the reader checks them against the counts;
  // the refined pillow's are stored at its pass vertices and spread back).
  std::map<size_t, size_t> counts;
  for (size_t i = 0; i < b.scene.objects.size(); ++i) counts[i] = b.scene.objects[i].mesh.positions.size();
  const ShadingData d = read_scene_shading_data(reader, b.scene);
  ASSERT_TRUE(d.visibility.count(0));  // the pillow
  EXPECT_EQ(d.visibility.at(0).coefficients.size(), counts[0] * size_t(d.visibility.at(0).terms));
  fs::remove(out);
}

TEST(BakeSubdivide, LevelOutsideTheRangeIsBadUsage) {
  const fs::path out = temp("bad.weftbundle");
  EXPECT_EQ(bake("--scene swatch --no-tables --subdivide " + std::to_string(kMaxSubdivision + 1) + " --out " +
                 out.string()),
            2);
  EXPECT_EQ(bake("--scene swatch --no-tables --subdivide -1 --out " + out.string()), 2);
  EXPECT_FALSE(fs::exists(out));
}
