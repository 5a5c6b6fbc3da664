// SgVisibility (methods/iwasaki_visibility.h) reconstructs d and ∇d only at the SG axes, from
// the PCA, when the lighting changes. Independent expectation: expand the vertex's whole grid
// from the PCA, take visibility_sdf.h's sdf_gradient of it, and look it up bilinearly at the
// axis's vertex-frame angles — what the runtime did before, for every vertex, at load.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "bake/visibility/scene_visibility.h"
#include "bake/visibility/visibility_sdf.h"
#include "methods/iwasaki/iwasaki_visibility.h"
#include "scene/scene_file.h"
#include "scene/vertex_pass_mesh.h"

using namespace weft;

namespace {

dvec3 expanded_lookup(const ObjectVisibility& o, size_t v, const SurfaceFrame& f, dvec3 w) {
  const int n = o.resolution, cells = n * n;
  const double h = std::numbers::pi / n;
  DistanceGrid d{n, n, std::vector<double>(cells)};
  for (int k = 0; k < cells; ++k) {
    double x = o.mean[k];
    for (int t = 0; t < o.terms; ++t) x += double(o.basis[size_t(t) * cells + k]) * o.coefficients[v * o.terms + t];
    d.values[k] = x;
  }
  const SdfGradient g = sdf_gradient(d, h, false);
  w = glm::normalize(w);
  const double theta = std::asin(std::clamp(glm::dot(w, f.u), -1.0, 1.0));
  const double phi = std::atan2(glm::dot(w, f.v), glm::dot(w, f.n));
  const double gi = std::clamp((theta + std::numbers::pi / 2) / h - 0.5, 0.0, n - 1.0);
  const double gj = std::clamp((phi + std::numbers::pi / 2) / h - 0.5, 0.0, n - 1.0);
  const int i0 = std::min(int(gi), n - 2), j0 = std::min(int(gj), n - 2);
  const double fi = gi - i0, fj = gj - j0;
  auto at = [&](int i, int j) { return dvec3(d.at(i, j), g.d_theta.at(i, j), g.d_phi.at(i, j)); };
  return (1 - fi) * ((1 - fj) * at(i0, j0) + fj * at(i0, j0 + 1)) + fi * ((1 - fj) * at(i0 + 1, j0) + fj * at(i0 + 1, j0 + 1));
}

// The pillow scene's cloth and its visibility baked on a 16² grid.
struct PillowVisibility {
  Scene scene;
  size_t cloth = 0;
  std::optional<ObjectVisibility> vis;
  const TriangleMesh& mesh() const { return scene.objects[cloth].mesh; }
};
PillowVisibility pillow_visibility() {
  PillowVisibility p;
  p.scene = load_scene_preset("pillow", WEFT_SOURCE_ASSETS "/scenes");
  for (size_t i = 0; i < p.scene.objects.size(); ++i)
    if (p.scene.objects[i].material == Material::cloth) p.cloth = i;
  SceneVisibilityOptions vo;
  vo.resolution = 16;
  p.vis = bake_object_visibility(p.scene, p.cloth, vo);
  return p;
}

TEST(SgVisibility, MatchesTheExpandedGridAtEverySgAxis) {
  const PillowVisibility p = pillow_visibility();
  const auto& vis = p.vis;
  ASSERT_TRUE(vis.has_value());
  const TriangleMesh& mesh = p.mesh();
  // Axes from overhead to below the horizon, sharp and broad (sharpness does not enter d).
  SgLighting sgs;
  for (const dvec3& a : {dvec3(0, 0, 1), dvec3(0.3, -0.5, 0.8), dvec3(-0.9, 0.1, 0.05), dvec3(0.2, 0.9, -0.4)})
    sgs.push_back({glm::normalize(a), 50.0, dvec3(1.0)});
  const SgVisibility s = SgVisibility::compute(*vis, mesh, sgs);
  ASSERT_EQ(s.vertices, mesh.positions.size());
  double worst = 0.0, spread = 0.0;
  for (size_t v = 0; v < s.vertices; v += 37) {
    const SurfaceFrame f = SurfaceFrame::from_normal_warp(mesh.normals[v], mesh.warps[v]);
    for (int k = 0; k < int(sgs.size()); ++k) {
      const dvec3 want = expanded_lookup(*vis, v, f, sgs[k].axis), got = s.at(v, k);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(want[c] - got[c]) / (1.0 + std::abs(want[c])));
      spread = std::max(spread, std::abs(want.x));
    }
  }
  EXPECT_LT(worst, 1e-5);  // float storage
  EXPECT_GT(spread, 0.1);  // the lookups saw real distances, not a flat grid
}

// A mesh with a pass subset is looked up at its pass vertices alone: there the values are those of
// the whole mesh's lookup, and every other vertex holds its corners' blend of them — the same blend
// the pass's shading gets, so the per-pixel rungs read what the per-vertex ones shade.
TEST(SgVisibility, OnAPassSubsetLooksUpPassVerticesAndBlendsTheRest) {
  const PillowVisibility p = pillow_visibility();
  const auto& vis = p.vis;
  ASSERT_TRUE(vis.has_value());
  TriangleMesh mesh = p.mesh();
  VertexPassMeshOptions po;
  po.keep_all_below = 0;  // the pillow is under the size at which a mesh keeps every vertex
  auto pass = std::make_shared<VertexPassMesh>(vertex_pass_mesh(mesh, po));
  ASSERT_FALSE(pass->whole());
  ASSERT_LT(pass->vertices.size(), mesh.positions.size() / 2);  // the pillow's sheets coarsen far
  SgLighting sgs;
  for (const dvec3& a : {dvec3(0, 0, 1), dvec3(0.3, -0.5, 0.8), dvec3(-0.9, 0.1, 0.05)})
    sgs.push_back({glm::normalize(a), 30.0, dvec3(1.0)});
  const SgVisibility whole = SgVisibility::compute(*vis, mesh, sgs);
  mesh.pass = pass;
  const SgVisibility subset = SgVisibility::compute(*vis, mesh, sgs);
  ASSERT_EQ(subset.vertices, mesh.positions.size());
  std::vector<bool> is_pass(mesh.positions.size(), false);
  for (uint32_t v : pass->vertices) is_pass[v] = true;
  double worst = 0.0;
  size_t blended = 0;
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    for (int k = 0; k < int(sgs.size()); ++k) {
      dvec3 want = whole.at(v, k);
      if (!is_pass[v]) {
        const auto& c = pass->corners[v];
        const glm::vec3 w = pass->weights[v];
        want = double(w.x) * whole.at(pass->vertices[c[0]], k) + double(w.y) * whole.at(pass->vertices[c[1]], k) +
               double(w.z) * whole.at(pass->vertices[c[2]], k);
        ++blended;
      }
      for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(want[i] - subset.at(v, k)[i]) / (1.0 + std::abs(want[i])));
    }
  EXPECT_LT(worst, 1e-5);  // float storage
  EXPECT_GT(blended, mesh.positions.size() / 2);
}

TEST(SgVisibility, RefusesAMeshOfAnotherSize) {
  ObjectVisibility o;
  o.resolution = 4;
  o.terms = 1;
  o.mean.assign(16, 0.0f);
  o.basis.assign(16, 0.0f);
  o.coefficients.assign(3, 0.0f);  // three vertices
  TriangleMesh m;
  m.positions.assign(2, dvec3(0));
  m.normals.assign(2, dvec3(0, 0, 1));
  m.warps.assign(2, dvec3(1, 0, 0));
  EXPECT_THROW(SgVisibility::compute(o, m, {}), std::invalid_argument);
}

}  // namespace
