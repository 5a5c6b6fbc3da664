// Parity: methods/sheer/sheer.glsl (the thin layer over iwasaki.glsl), drawn by the sheer
// methods' GPU side (per pixel `sheer`, and `sheer_vertex` per vertex, interpolated) on the GL
// driver (llvmpipe here) and read back as premultiplied source and alpha, agrees with the C++
// evaluation (methods/sheer/sheer.cpp over iwasaki.cpp, iwasaki_visibility.cpp's SDF lookup and the
// baked κ) within 1e−3 relative at sample pixels, on the curtain lit from both sides. The cloth is
// drawn alone into a target cleared to zero, so a pixel holds the nearest layer's (source, α); the
// C++ side finds that point by casting the pixel's camera ray (Embree), as iwasaki_parity_test does.
#include <gtest/gtest.h>

#include <GLES3/gl3.h>

#include <array>
#include <cmath>
#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "bake/visibility/scene_visibility.h"
#include "bake/visibility/sigmoid_gain.h"
#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "methods/iwasaki/iwasaki_visibility.h"
#include "methods/registry.h"
#include "methods/sheer/sheer.h"
#include "reference/ray_scene.h"
#include "scene/scene_file.h"
#include "support/parity_bake_settings.h"
#include "support/ray_pixels.h"
#include "support/strict_glsl.h"

using namespace weft;

namespace {

// The curtain hangs in the x = const plane facing ±x (the camera is at +x, the window at −x):
// lobes on both sides, one low and grazing so the pleats and the floor shadow part of it.
SgLighting test_lights() {
  SgLighting l;
  l.push_back({glm::normalize(dvec3(-0.9, 0.2, 0.3)), 30.0, dvec3(4.0, 3.5, 3.0)});   // the window, behind
  l.push_back({glm::normalize(dvec3(0.8, -0.5, 0.3)), 12.0, dvec3(0.8, 1.0, 1.3)});   // the room, in front
  l.push_back({glm::normalize(dvec3(0.15, 0.95, 0.1)), 60.0, dvec3(2.0, 1.8, 1.5)});  // grazing along the pleats
  l.push_back({glm::normalize(dvec3(0.0, 0.0, 1.0)), 3.0, dvec3(0.4, 0.4, 0.5)});
  return l;
}

void check_parity(const std::string& method_name) {
  const bool per_vertex = method_name == "sheer_vertex";
  Scene scene = load_scene_preset("curtain", WEFT_SOURCE_ASSETS "/scenes");
  const Fabric fabric = load_fabric_preset("polyester_voile", WEFT_SOURCE_ASSETS "/fabrics");
  size_t cloth_index = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].material == Material::cloth) {
      scene.objects[i].fabric = fabric.name;
      cloth_index = i;
    }
  auto data = std::make_shared<ShadingData>();
  data->tables.emplace(fabric.name, bake_weighting_tables(fabric, test::parity_bake_settings()));
  SceneVisibilityOptions vo;
  vo.resolution = 16;
  auto baked = bake_object_visibility(scene, cloth_index, vo);
  ASSERT_TRUE(baked) << "the curtain bakes no visibility: the visibility path would go untested";
  data->visibility.emplace(cloth_index, std::move(*baked));
  SigmoidGainTableSpec ks;
  ks.sigma_l_count = ks.sigma_prime_count = 5;
  ks.beta_count = 9;
  data->kappa = fit_sigmoid_gain_table(ks);

  const int w = 80, h = 60;
  const SgLighting sgs = test_lights();
  const TriangleMesh& mesh = scene.objects[cloth_index].mesh;
  gpu::EglContext ctx = gpu::EglContext::headless();
  const methods::RuntimeMethod& method = methods::method(method_name);
  ASSERT_TRUE(method.see_through);
  auto cloth = method.make_gpu(gpu::ClothMethodSetup{16, data, {}});
  const size_t handle = cloth->add_object(cloth_index, mesh, fabric);
  cloth->set_lighting(handle, sgs, *cloth->prepare_lighting(handle, sgs));
  gpu::OffscreenTarget target(w, h);
  target.bind();
  glViewport(0, 0, w, h);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  const Camera& cam = scene.camera;
  const glm::mat4 vp = glm::perspective(float(glm::radians(cam.fov_deg)), float(w) / h, 0.05f, 100.0f) *
                       glm::lookAt(glm::vec3(cam.position), glm::vec3(cam.target), glm::vec3(cam.up));
  cloth->draw(handle, vp, glm::vec3(cam.position), sgs);
  std::vector<float> px(size_t(w) * h * 4);
  glFinish();
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, px.data());
  auto gpu_at = [&](int x, int y) {
    const float* p = &px[(size_t(h - 1 - y) * w + x) * 4];
    return glm::dvec4(p[0], p[1], p[2], p[3]);
  };

  // The C++ side, from the same data.
  const WeightingTables& tables = data->tables.at(fabric.name);
  const ClothBsdf bsdf(fabric, tables.tangent_samples);
  const ThinParams layer = thin_params(fabric);
  const SgVisibility grids = SgVisibility::compute(data->visibility.at(cloth_index), mesh, sgs);
  const RayScene rays(scene);
  int compared = 0;
  double worst = 0, visibility_effect = 0, alpha_min = 1, alpha_max = 0;
  for (int y = 1; y < h - 1; y += 2)
    for (int x = 1; x < w - 1; x += 2) {
      const dvec3 dir = camera_ray(cam, w, h, x + 0.5, y + 0.5);
      const auto hit = rays.intersect(cam.position, dir);
      if (!hit || hit->object != cloth_index) continue;
      const double b0 = 1 - hit->b1 - hit->b2;
      if (std::min({b0, hit->b1, hit->b2}) < 0.02) continue;
      if (!test::interior_pixel(rays, cam, w, h, x, y, cloth_index)) continue;
      const auto& tri = mesh.triangles[hit->triangle];
      const dvec3 bary(b0, hit->b1, hit->b2);
      auto shade = [&](dvec3 b, std::array<uint32_t, 3> corners, dvec3 sdf_bary, bool with_visibility) {
        const test::MeshPoint m = test::mesh_point(mesh, tri, b);
        const dvec3 p = m.position, warp = m.warp;
        dvec3 n = m.normal;
        const dvec3 wo = glm::normalize(cam.position - p);
        const SurfaceFrame mesh_frame = SurfaceFrame::from_normal_warp(n, warp);
        SurfaceFrame facing = mesh_frame;
        if (glm::dot(facing.n, wo) < 0) facing.n = -facing.n, facing.v = glm::cross(facing.n, facing.u);
        IwasakiVisibility vis;
        vis.kappa = &*data->kappa;
        vis.sdf = [&](int sg, const ThreadFrame& tf, double theta, double phi, double& d, double& dt, double& dp) {
          const SdfSample s = sdf_in_sample_frame(grids, sg, facing, corners, sdf_bary, tf, theta, phi);
          d = s.d, dt = s.d_dtheta, dp = s.d_dphi;
        };
        std::vector<double> shares;
        for (int k = 0; k < int(sgs.size()); ++k) {
          dvec3 s(0);
          for (int c = 0; c < 3; ++c) s += sdf_bary[c] * grids.at(corners[c], k);
          shares.push_back(sheer_sdf_share(sgs[k], mesh_frame, s, &*data->kappa));
        }
        const ThinShade t = with_visibility ? sheer_radiance(bsdf, tables, layer, mesh_frame, wo, sgs, &vis, shares)
                                            : sheer_radiance(bsdf, tables, layer, mesh_frame, wo, sgs);
        return glm::dvec4(t.source, t.alpha);
      };
      auto cpu_at = [&](bool with_visibility) {
        if (!per_vertex) return shade(bary, {tri[0], tri[1], tri[2]}, bary, with_visibility);
        glm::dvec4 sum(0);
        for (int k = 0; k < 3; ++k) {
          dvec3 one(0);
          one[k] = 1;
          sum += bary[k] * shade(one, {tri[k], tri[k], tri[k]}, dvec3(1, 0, 0), with_visibility);
        }
        return sum;
      };
      const glm::dvec4 cpu = cpu_at(true), open = cpu_at(false);
      visibility_effect = std::max(visibility_effect, glm::length(dvec3(open - cpu)) / glm::length(dvec3(open)));
      alpha_min = std::min(alpha_min, cpu.a), alpha_max = std::max(alpha_max, cpu.a);
      const glm::dvec4 g = gpu_at(x, y);
      const double scale = std::max({cpu.r, cpu.g, cpu.b});
      ASSERT_GT(scale, 0.0) << "pixel " << x << "," << y;
      for (int k = 0; k < 4; ++k) {
        const double e = std::abs(g[k] - cpu[k]) / (k == 3 ? 1.0 : scale);
        worst = std::max(worst, e);
        EXPECT_LT(e, 1e-3) << "pixel " << x << "," << y << " channel " << k << ": GLSL " << g[k] << ", C++ " << cpu[k];
      }
      ++compared;
    }
  std::printf("%s curtain/voile: %d pixels compared, worst relative difference %.2e; visibility changes a pixel by up to "
              "%.1f %%; alpha %.3f..%.3f\n",
              method_name.c_str(), compared, worst, 100 * visibility_effect, alpha_min, alpha_max);
  EXPECT_GT(compared, 40);
  EXPECT_GT(visibility_effect, 0.05) << "visibility hardly changes any compared pixel: the path went untested";
  // τ = 0.4: e^{−0.4} = 0.67 head-on, less at an angle; the layer must be neither opaque nor absent.
  EXPECT_LT(alpha_max, std::exp(-0.4) + 1e-6);
  EXPECT_GT(alpha_min, 0.05);
}

TEST(SheerParity, PerPixelGlslMatchesCpp) { check_parity("sheer"); }
TEST(SheerParity, PerVertexGlslMatchesCpp) { check_parity("sheer_vertex"); }

}  // namespace
