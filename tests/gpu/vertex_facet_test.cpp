// The per-vertex rungs cut each SG by the facet's plane (iwasaki_vertex.frag; C++:
// facet_interpolated_radiance). A flat two-triangle quad whose vertex normals all lean 8° away from
// its plane, under a sharp SG 6.5° above the shading horizon but 1.5° below the facet's plane and
// a high SG neither plane cuts: the reference's rays start from the flat triangle, so the low SG
// keeps only its share above the facet's plane. Expected per pixel: the high SG's radiance at the
// three vertices blended with the barycentrics, plus the low SG's blended and scaled by that share
// by quadrature (the SG-warped grid, independent of facet_horizon_factor's closed form). A draw
// that sums the SGs per vertex and interpolates the sum (no facet) is off by the low SG's whole
// blocked part.
#include <gtest/gtest.h>

#include <GLES3/gl3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <span>
#include <vector>

#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "gpu/scene_renderer.h"
#include "methods/iwasaki/iwasaki.h"
#include "methods/registry.h"
#include "reference/ray_scene.h"
#include "scene/scene.h"
#include "support/facet_share.h"
#include "support/parity_bake_settings.h"
#include "support/ray_pixels.h"
#include "support/strict_glsl.h"

using namespace weft;

namespace {

constexpr double kLean = 8.0;  // degrees between the vertex normals and the quad's plane

// Towards −y (the side the normals lean to) at `elevation` degrees above the quad's plane.
dvec3 towards_minus_y(double elevation) {
  const double e = glm::radians(elevation);
  return dvec3(0.0, -std::cos(e), std::sin(e));
}

Scene leaning_quad(const std::string& fabric) {
  const double lean = glm::radians(kLean);
  SceneObject o;
  o.name = "quad";
  o.material = Material::cloth;
  o.fabric = fabric;
  TriangleMesh& m = o.mesh;
  m.positions = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.normals.assign(4, dvec3(0.0, -std::sin(lean), std::cos(lean)));  // leaning towards −y, the low SG's side
  m.warps.assign(4, dvec3(1.0, 0.0, 0.0));
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  Scene s;
  s.name = "leaning_quad";
  s.camera.position = dvec3(0.0, 1.6, 1.2);  // across the quad from the low SG: its forward scattering
  s.camera.target = dvec3(0.0);
  s.camera.up = dvec3(0, 0, 1);
  s.camera.fov_deg = 50;
  s.objects.push_back(std::move(o));
  return s;
}

}  // namespace

TEST(VertexFacet, PerVertexSgsAreCutByTheFacetsPlane) {
  const std::string name = "polyester_satin_charmeuse";
  const Scene scene = leaning_quad(name);
  const Fabric fabric = load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics");
  auto data = std::make_shared<ShadingData>();
  data->tables.emplace(name, bake_weighting_tables(fabric, test::parity_bake_settings()));
  const SphericalGaussian low{towards_minus_y(-1.5), 1000.0, dvec3(60.0, 50.0, 40.0)};
  const SphericalGaussian high{glm::normalize(dvec3(0.3, -0.6, 0.8)), 40.0, dvec3(2.0, 2.0, 2.0)};
  const SgLighting sgs = {high, low};

  const int w = 64, h = 48;
  gpu::EglContext ctx = gpu::EglContext::headless();
  gpu::SceneRenderer renderer(scene, {fabric}, methods::method("iwasaki_vertex"), 16, data);
  renderer.set_lighting(sgs);
  gpu::OffscreenTarget target(w, h);
  target.bind();
  renderer.draw(scene.camera, w, h);
  const Image image = gpu::read_linear_image(w, h);
  GLint outputs = 0, inputs = 0;  // what bounds the SGs a per-vertex draw can carry (iwasaki_cloth.cpp's facet_draw)
  glGetIntegerv(GL_MAX_VERTEX_OUTPUT_COMPONENTS, &outputs);
  glGetIntegerv(GL_MAX_FRAGMENT_INPUT_COMPONENTS, &inputs);
  std::printf("GL_MAX_VERTEX_OUTPUT_COMPONENTS %d, GL_MAX_FRAGMENT_INPUT_COMPONENTS %d: up to %d SGs per vertex\n", outputs,
              inputs, 4 * ((std::min(outputs, inputs) - 8) / 12));

  const WeightingTables& tables = data->tables.at(name);
  const ClothBsdf bsdf(fabric, tables.tangent_samples);
  const TriangleMesh& mesh = scene.objects[0].mesh;
  const dvec3 facet(0, 0, 1), ns = mesh.normals[0];
  const double share = test::facet_share_by_quadrature(low, ns, facet);
  ASSERT_LT(share, 0.5) << "the facet should block most of the low SG";
  ASSERT_GT(test::facet_share_by_quadrature(low, ns, ns), 0.99) << "the shading plane should let the low SG through";

  const RayScene rays(scene);
  int compared = 0;
  double worst_share = 0, worst_twin = 0, low_part = 1.0;
  for (int y = 1; y < h - 1; y += 3)
    for (int x = 1; x < w - 1; x += 3) {
      const auto hit = rays.intersect(scene.camera.position, camera_ray(scene.camera, w, h, x + 0.5, y + 0.5));
      if (!hit || !test::interior_pixel(rays, scene.camera, w, h, x, y, 0)) continue;
      const auto& tri = mesh.triangles[hit->triangle];
      const dvec3 bary(1 - hit->b1 - hit->b2, hit->b1, hit->b2);
      if (std::min({bary.x, bary.y, bary.z}) < 0.02) continue;  // off the diagonal: both sides pick one triangle
      // Each SG's radiance at the three vertices (no occluder: no visibility).
      std::array<std::vector<dvec3>, 3> at;
      dvec3 high_blend(0), low_blend(0);
      for (int i = 0; i < 3; ++i) {
        const dvec3 p = mesh.positions[tri[i]];
        const dvec3 wo = glm::normalize(scene.camera.position - p);
        const SurfaceFrame frame = SurfaceFrame::from_normal_warp(mesh.normals[tri[i]], mesh.warps[tri[i]]);
        for (size_t k = 0; k < sgs.size(); ++k) at[i].push_back(iwasaki_sg_radiance(bsdf, tables, frame, wo, sgs, k).radiance);
        high_blend += bary[i] * at[i][0];
        low_blend += bary[i] * at[i][1];
      }
      ASSERT_GT(low_blend.r, 0.2 * high_blend.r) << "the low SG should light the quad";
      low_part = std::min(low_part, low_blend.r / (low_blend.r + high_blend.r));
      const dvec3 g = image.at(x, y);
      // The low SG's share the GPU kept, against the quadrature's.
      for (int c = 0; c < 3; ++c) {
        const double kept = (g[c] - high_blend[c]) / low_blend[c];
        worst_share = std::max(worst_share, std::abs(kept - share));
      }
      // The C++ twin (the parity test pins it on the showroom scenes) gives the same pixel.
      const dvec3 twin = facet_interpolated_radiance(sgs, {}, {at[0], at[1], at[2]}, bary, ns, facet);
      for (int c = 0; c < 3; ++c) worst_twin = std::max(worst_twin, std::abs(twin[c] - g[c]) / twin[c]);
      ++compared;
    }
  std::printf("%d pixels; the low SG's share above the facet %.3f (quadrature), worst |GPU's − quadrature's| %.1e; "
              "the low SG is at least %.0f %% of a pixel's blend without the facet; C++ twin worst %.1e\n",
              compared, share, worst_share, 100 * low_part, worst_twin);
  EXPECT_GT(compared, 20);
  // facet_horizon_factor's closed form where one plane cuts the lobe: within 0.001 of the quadrature
  // (facet_horizon_test), plus float rendering.
  EXPECT_LT(worst_share, 0.01);
  EXPECT_LT(worst_twin, 1e-3);
}
