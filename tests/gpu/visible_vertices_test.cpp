// The per-vertex passes for the vertices a frame shows only (methods/vertex_pass/visible_vertices.h),
// on a pillow seen from its side (the far half of its sheet faces away), its lower part hidden
// behind a cloth panel and its left end cut off by the frame's edge:
//  - the vertices marked are those of the triangles that a ray through some pixel centre hits
//    first (Embree, not the GL), give or take the triangles at a silhouette;
//  - the frame, with the cloth's depth drawn first, is the frame with every vertex computed and
//    no depth first;
//  - with reuse (a share of the vertices per draw), an eye that jumps to the other side gets the
//    vertices it reveals computed at once: the frame is that side's full frame but for the few
//    vertices both sides see, where the values kept from the first side would be far off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "methods/iwasaki/iwasaki_cloth.h"
#include "methods/vertex_pass/visible_vertices.h"
#include "reference/ray_scene.h"
#include "scene/procedural_meshes.h"
#include "scene/scene.h"
#include "support/parity_bake_settings.h"

using namespace weft;

namespace {

constexpr int kWidth = 96, kHeight = 72;

Scene pillow_behind_panel(const std::string& fabric) {
  Scene s;
  SceneObject pillow;
  pillow.name = "pillow";
  pillow.material = Material::cloth;
  pillow.fabric = fabric;
  pillow.mesh = pillow_mesh(1.0, 0.7, 0.3, 0.02, 24);
  finish_mesh(pillow.mesh, true, "pillow");
  SceneObject panel;
  panel.name = "panel";
  panel.material = Material::cloth;
  panel.fabric = fabric;
  panel.mesh = parametric_grid(4, 2, [](double u, double v) { return glm::dvec3(u - 0.3, -0.8, 0.12 * v); });
  finish_mesh(panel.mesh, true, "panel");
  s.objects = {pillow, panel};
  s.camera.position = glm::dvec3(0.25, -2.4, 0.14);
  s.camera.target = glm::dvec3(0.25, 0.0, 0.14);
  s.camera.fov_deg = 24.0;
  return s;
}

Camera turned(const Camera& c, double deg) {
  Camera out = c;
  const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), glm::radians(deg), glm::dvec3(0, 0, 1));
  out.position = glm::dvec3(r * glm::dvec4(c.position - c.target, 0.0)) + c.target;
  return out;
}

glm::mat4 view_projection(const Camera& c) {  // as gpu::SceneRenderer::draw
  const glm::mat4 proj = glm::perspective(float(glm::radians(c.fov_deg)), float(kWidth) / kHeight, 0.05f, 100.0f);
  return proj * glm::lookAt(glm::vec3(c.position), glm::vec3(c.target), glm::vec3(c.up));
}

struct Frame {
  std::vector<float> rgba;
  size_t pillow_visible = 0;
};

// The first `objects` objects drawn by one per-vertex quadrature rung into `target`; `depth_first`:
// their depth written first (ClothMethod::draw_depth), as gpu::SceneRenderer does.
Frame draw(gpu::IwasakiCloth& cloth, const Scene& s, const Camera& c, const SgLighting& sgs, gpu::OffscreenTarget& target,
           size_t objects = 2, bool depth_first = false) {
  target.bind();
  glViewport(0, 0, kWidth, kHeight);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (depth_first) {
    for (size_t i = 0; i < objects; ++i) EXPECT_TRUE(cloth.draw_depth(i, view_projection(c)));
  }
  for (size_t i = 0; i < objects; ++i) cloth.draw(i, view_projection(c), glm::vec3(c.position), sgs);
  return {target.read_rgba(), cloth.visible_vertices(0)};
}

double relative_rmse(const std::vector<float>& a, const std::vector<float>& b) {
  double d2 = 0, sum = 0;
  for (size_t i = 0; i < a.size(); i += 4)
    for (int ch = 0; ch < 3; ++ch) d2 += (a[i + ch] - b[i + ch]) * (a[i + ch] - b[i + ch]), sum += std::abs(b[i + ch]);
  return std::sqrt(d2 / double(a.size())) / (sum / double(a.size()));
}

double worst_relative(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0, peak = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, double(std::abs(a[i] - b[i]))), peak = std::max(peak, double(std::abs(b[i])));
  return worst / peak;
}

}  // namespace

TEST(VisibleVertices, OnlyTheShownVerticesAreComputedAndTheFrameIsTheSame) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  if (!gpu::VisibleVertices::supported()) GTEST_SKIP() << "the GL has no GLES 3.2 fragment storage: every vertex is computed";
  const std::string name = "linen_plain";
  const Scene scene = pillow_behind_panel(name);
  const Fabric fabric = load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics");
  auto data = std::make_shared<ShadingData>();
  data->tables.emplace(name, bake_weighting_tables(fabric, test::parity_bake_settings()));
  // A broad lobe (quadrature) and a sharp one (iwasaki): both kinds of block.
  const SgLighting sgs = {{glm::normalize(glm::dvec3(0.2, -0.5, 0.8)), 2.0, glm::dvec3(1.0, 0.9, 0.8)},
                          {glm::normalize(glm::dvec3(-0.4, -0.6, 0.7)), 60.0, glm::dvec3(4.0, 3.5, 3.0)}};
  gpu::IwasakiCloth cloth(data, gpu::IwasakiCloth::Evaluation::per_vertex, gpu::iwasaki_quadrature_shaders());
  // Its per-SG blocks carry kept values on (the kiosk's reuse by degrees); per pixel nothing is kept.
  EXPECT_TRUE(cloth.reuse_follows_camera());
  EXPECT_FALSE(gpu::IwasakiCloth(data, gpu::IwasakiCloth::Evaluation::per_pixel).reuse_follows_camera());
  for (size_t i = 0; i < scene.objects.size(); ++i) cloth.add_object(i, scene.objects[i].mesh, fabric);
  gpu::OffscreenTarget target(kWidth, kHeight);

  // The pillow's vertices whose triangles a pixel-centre ray hits first.
  const RayScene rays(scene);
  std::set<uint32_t> seen;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const auto hit = rays.intersect(scene.camera.position, camera_ray(scene.camera, kWidth, kHeight, x + 0.5, y + 0.5));
      if (hit && hit->object == 0) seen.insert(scene.objects[0].mesh.triangles[hit->triangle].begin(),
                                               scene.objects[0].mesh.triangles[hit->triangle].end());
    }
  const size_t vertices = scene.objects[0].mesh.positions.size();

  cloth.set_visible_vertices_only(true);
  const Frame culled = draw(cloth, scene, scene.camera, sgs, target, 2, true);
  cloth.set_visible_vertices_only(false);
  const Frame all = draw(cloth, scene, scene.camera, sgs, target);
  std::printf("pillow: %zu vertices, %zu marked visible, %zu under a pixel-centre ray; frame's worst difference %.2e\n",
              vertices, culled.pillow_visible, seen.size(), worst_relative(culled.rgba, all.rgba));
  ASSERT_LT(seen.size(), vertices / 2) << "the view should hide most of the pillow";
  EXPECT_GE(double(culled.pillow_visible), 0.97 * double(seen.size()));
  EXPECT_LE(double(culled.pillow_visible), 1.15 * double(seen.size()) + 8.0);
  EXPECT_EQ(all.pillow_visible, vertices);
  EXPECT_LE(worst_relative(culled.rgba, all.rgba), 1e-6) << "computing only the visible vertices, or the depth first, changed the frame";

  // Reuse: one share in 1000 per draw, and the eye jumps to the pillow's other side (the panel,
  // one sheet seen from both sides, left out).
  const Camera other = turned(scene.camera, 180.0);
  cloth.set_vertex_refresh(1000);
  cloth.refresh_all();
  cloth.set_visible_vertices_only(true);
  draw(cloth, scene, scene.camera, sgs, target, 1);
  const Frame jumped = draw(cloth, scene, other, sgs, target, 1);
  cloth.set_visible_vertices_only(false);
  cloth.refresh_all();
  draw(cloth, scene, scene.camera, sgs, target, 1);
  const Frame kept = draw(cloth, scene, other, sgs, target, 1);
  cloth.set_vertex_refresh(1);
  const Frame full = draw(cloth, scene, other, sgs, target, 1);
  const double revealed = relative_rmse(jumped.rgba, full.rgba), stale = relative_rmse(kept.rgba, full.rgba);
  std::printf("after the jump, one share in 1000: visible only %.2f %% off the full frame, every vertex kept %.2f %%\n",
              100 * revealed, 100 * stale);
  ASSERT_GT(stale, 0.2) << "the jump should show vertices the first side did not";
  EXPECT_LT(revealed, 0.02);
}
