// The visibility bake over the per-vertex passes' subset (scene/vertex_pass_mesh.h) on the pillow,
// its cloth refined past the subset's threshold: rays are cast at the pass vertices only, and every
// other vertex takes its corners' blend (the SDF) or its heaviest corner's bits (the mask). Against
// the same bake casting at every vertex (the independent expectation: each vertex's own rays):
//  - the SDF reconstructed at the vertices that were not cast is within one cell of the 16² grid
//    (π/16) of their own on average, and the masks differ in few bits;
//  - the bake reports casting the subset only.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>

#include "bake/visibility/scene_visibility.h"
#include "bake/visibility/visibility_mask_bake.h"
#include "scene/mesh_subdivision.h"
#include "scene/scene_file.h"
#include "scene/vertex_pass_mesh.h"

using namespace weft;

namespace {

double sdf_at(const ObjectVisibility& o, size_t v, int cell) {
  const int cells = o.resolution * o.resolution;
  double x = o.mean[size_t(cell)];
  for (int t = 0; t < o.terms; ++t) x += double(o.basis[size_t(t) * cells + cell]) * o.coefficients[v * o.terms + t];
  return x;
}

}  // namespace

TEST(PassVisibility, VerticesNotCastTakeTheirCornersVisibility) {
  Scene scene = load_scene_preset("pillow", WEFT_SOURCE_ASSETS "/scenes");
  size_t cloth = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].material == Material::cloth) cloth = i;
  scene = refine_cloth_meshes(std::move(scene), 1);
  const TriangleMesh& mesh = scene.objects[cloth].mesh;
  ASSERT_GE(mesh.positions.size(), VertexPassMeshOptions::kKeepAllVertices);
  SceneVisibilityOptions vo;
  vo.resolution = 16;
  SceneVisibilityStats every_stats, pass_stats;
  const auto every = bake_object_visibility(scene, cloth, vo, {}, &every_stats);
  const auto every_mask = bake_visibility_mask(scene, cloth, 16);
  // The subset the simplifier's budget allows without an edge bound: the coarsest it gives.
  scene.objects[cloth].mesh.pass = std::make_shared<const VertexPassMesh>(vertex_pass_mesh(mesh));
  const VertexPassMesh& pass = pass_of(scene.objects[cloth].mesh);
  ASSERT_FALSE(pass.whole());
  const auto subset = bake_object_visibility(scene, cloth, vo, {}, &pass_stats);
  const auto subset_mask = bake_visibility_mask(scene, cloth, 16);
  ASSERT_TRUE(every && subset && every_mask && subset_mask);
  EXPECT_EQ(every_stats.vertices, mesh.positions.size());
  EXPECT_EQ(pass_stats.vertices, pass.vertices.size());
  ASSERT_EQ(subset->vertex_count(), mesh.positions.size());
  ASSERT_EQ(subset_mask->vertex_count(), mesh.positions.size());
  std::vector<bool> cast(mesh.positions.size(), false);
  for (uint32_t v : pass.vertices) cast[v] = true;
  double sum = 0.0;
  size_t n = 0, bits = 0, differing = 0;
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    if (cast[v]) continue;
    for (int cell = 0; cell < 16 * 16; ++cell, ++n) sum += std::abs(sdf_at(*subset, v, cell) - sdf_at(*every, v, cell));
    for (int b = 0; b < subset_mask->blocks(); ++b) {
      const size_t w = v * size_t(subset_mask->blocks()) + size_t(b);
      differing += size_t(std::popcount(subset_mask->words[w] ^ every_mask->words[w]));
      bits += 64;
    }
  }
  ASSERT_GT(n, 0u);
  EXPECT_LT(sum / double(n), std::numbers::pi / 16) << "mean |Δd| at the vertices not cast (radians): within a grid cell";
  EXPECT_LT(double(differing) / double(bits), 0.05) << "mask bits that differ at the vertices not cast";
}
