// Floors and occluders get the cloth's baked visibility (methods/lambert_visibility.h): a graded floor
// under a Lambertian pillow, its visibility baked as the cloth's is, shaded per vertex from the
// PCA's SDF at the SG axes. Independent expectation: E(v) = Σ_k ∫ G_k(ω) max(ω·n, 0) V(ω) dω by
// ray-cast quadrature over the hemisphere (one Embree shadow ray per direction, equal-area cells).
// Then the GPU side: SceneRenderer draws the floor with those per-vertex values (parity with the
// C++ interpolation at sample pixels), also when the lighting is prepared on another thread.
#include <gtest/gtest.h>

#include <cmath>
#include <future>
#include <numbers>

#include "bake/visibility/scene_visibility.h"
#include "bake/visibility/sigmoid_gain.h"
#include "gpu/egl_context.h"
#include "gl/offscreen_target.h"
#include "gpu/scene_renderer.h"
#include "methods/iwasaki/iwasaki_visibility.h"
#include "methods/lambert_visibility.h"
#include "methods/registry.h"
#include "reference/ray_scene.h"
#include "scene/procedural_meshes.h"
#include "scene/scene_file.h"

using namespace weft;

namespace {

constexpr double kPi = std::numbers::pi;

const char* kScene = R"({
  "name": "floor_shadow", "camera": {"position": [0, -3, 2], "target": [0, 0, 0], "up": [0, 0, 1], "fov_deg": 40},
  "environment": "studio",
  "objects": [
    {"name": "box", "material": "lambertian", "albedo": [0.5, 0.5, 0.5],
     "mesh": {"generator": "pillow", "size_x": 0.8, "size_y": 0.6, "height": 0.45, "wrinkle": 0.0, "resolution": 12}},
    {"name": "floor", "material": "lambertian", "albedo": [0.5, 0.5, 0.5],
     "mesh": {"generator": "quad", "size_x": 8, "size_y": 8, "fine_size": 2.4, "fine_spacing": 0.1, "growth": 1.5}}
  ]})";

SphericalGaussian sg(double elevation_deg, double azimuth_deg, double sharpness, double amplitude) {
  const double e = elevation_deg * kPi / 180, a = azimuth_deg * kPi / 180;
  return {dvec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)), sharpness, dvec3(amplitude)};
}

// A sun, a broad sky and a low window: sharp, wide and grazing lobes.
const SgLighting kLights = {sg(40, -60, 300, 40.0), sg(90, 0, 2.5, 0.6), sg(12, 150, 25, 4.0)};

// Σ_k ∫ G_k max(ω·n, 0) V dω over the upper hemisphere (the floor's normal is +z): cells of equal
// solid angle in (z = cos θ, φ), midpoints; directions that carry no light cast no ray.
double quadrature_irradiance(const RayScene& rays, const dvec3& origin, int nz, int nphi) {
  const double cell = (1.0 / nz) * (2 * kPi / nphi);
  double e = 0;
  for (int i = 0; i < nz; ++i) {
    const double z = (i + 0.5) / nz, r = std::sqrt(1 - z * z);
    for (int j = 0; j < nphi; ++j) {
      const double phi = (j + 0.5) * 2 * kPi / nphi;
      const dvec3 w(r * std::cos(phi), r * std::sin(phi), z);
      double radiance = 0;
      for (const auto& g : kLights) radiance += g(w).r;
      if (radiance * z < 1e-7) continue;
      if (rays.unoccluded(origin, w)) e += radiance * z * cell;
    }
  }
  return e;
}

}  // namespace

TEST(GradedQuad, FineWhereTheObjectsStandAndCoarseOutside) {
  const std::vector<double> axis = graded_axis(40.0, 2.0, 0.05, 1.3);
  EXPECT_DOUBLE_EQ(axis.front(), -20.0);
  EXPECT_DOUBLE_EQ(axis.back(), 20.0);
  for (size_t i = 1; i < axis.size(); ++i) {
    const double step = axis[i] - axis[i - 1];
    ASSERT_GT(step, 0.0);
    if (std::abs(axis[i]) <= 1.0 + 1e-9 && std::abs(axis[i - 1]) <= 1.0 + 1e-9) {
      EXPECT_LE(step, 0.05 + 1e-12);
    }
  }
  EXPECT_LT(axis.size(), 80u);  // 40 fine cells plus a geometric tail each side, not 800 uniform ones
  const TriangleMesh m = graded_quad_mesh(40.0, 30.0, 2.0, 0.05, 1.3);
  double area = 0;
  for (const auto& t : m.triangles) {
    const dvec3 c = glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
    EXPECT_GT(c.z, 0.0);  // every triangle faces +z
    area += 0.5 * glm::length(c);
  }
  EXPECT_NEAR(area, 40.0 * 30.0, 1e-6);
}

TEST(LambertVisibility, FloorShadowMatchesRayCastQuadrature) {
  const Scene scene = parse_scene(kScene, "floor_shadow", ".");
  const size_t floor = 1;
  const TriangleMesh& mesh = scene.objects[floor].mesh;
  ASSERT_EQ(mesh.warps.size(), mesh.positions.size());  // finish_mesh frames meshes without UVs too
  SceneVisibilityOptions opt;
  opt.resolution = 64;
  const auto vis = bake_object_visibility(scene, floor, opt);
  ASSERT_TRUE(vis.has_value());
  const SgVisibility at_axes = SgVisibility::compute(*vis, mesh, kLights);
  const SigmoidGainTable kappa = fit_sigmoid_gain_table(SigmoidGainTableSpec{});

  const RayScene rays(scene);
  double sq_shadowed = 0, sq_open = 0, sum_ref = 0;
  int n = 0, in_shadow = 0;
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const dvec3 p = mesh.positions[v];
    if (std::abs(p.x) > 1.2 || std::abs(p.y) > 1.2 || v % 3) continue;  // a third of the fine centre
    const SurfaceFrame f = SurfaceFrame::from_normal_warp(mesh.normals[v], mesh.warps[v]);
    const double ref = quadrature_irradiance(rays, p + rays.ray_epsilon() * f.n, 200, 600);
    const double approx = lambert_irradiance(kLights, f, &at_axes, v, &kappa).r;
    const double open = lambert_irradiance(kLights, f, nullptr, v, nullptr).r;
    ASSERT_TRUE(std::isfinite(approx));
    EXPECT_LE(approx, open * (1 + 1e-12));  // visibility only takes light away
    in_shadow += ref < 0.8 * open;
    sq_shadowed += (approx - ref) * (approx - ref);
    sq_open += (open - ref) * (open - ref);
    sum_ref += ref;
    ++n;
  }
  ASSERT_GT(n, 150);
  const double mean = sum_ref / n;
  const double err = std::sqrt(sq_shadowed / n) / mean, err_open = std::sqrt(sq_open / n) / mean;
  RecordProperty("shadowed_error", std::to_string(err));
  RecordProperty("unshadowed_error", std::to_string(err_open));
  std::printf("floor vertices %d (%d in shadow): relative RMSE %.4f with visibility, %.4f without\n", n, in_shadow, err,
              err_open);
  EXPECT_GT(in_shadow, n / 10);  // the pillow really shades the floor
  EXPECT_LT(err, 0.10);
  EXPECT_LT(err, 0.3 * err_open);
}

TEST(LambertVisibility, SceneRendererShadesTheFloorWithTheBundlesVisibility) {
  const Scene scene = parse_scene(kScene, "floor_shadow", ".");
  const size_t floor = 1;
  const TriangleMesh& mesh = scene.objects[floor].mesh;
  auto data = std::make_shared<ShadingData>();
  SceneVisibilityOptions opt;
  opt.resolution = 32;
  data->visibility.emplace(floor, *bake_object_visibility(scene, floor, opt));
  SigmoidGainTableSpec ks;
  ks.sigma_l_count = ks.sigma_prime_count = 5;
  ks.beta_count = 9;
  data->kappa = fit_sigmoid_gain_table(ks);

  const int w = 96, h = 72;
  gpu::EglContext ctx = gpu::EglContext::headless();
  gpu::OffscreenTarget target(w, h);
  auto frame = [&](gpu::SceneRenderer& r) {
    target.bind();
    r.draw(scene.camera, w, h);
    return gpu::read_linear_image(w, h);
  };
  gpu::SceneRenderer shadowed(scene, {}, methods::method("sgpoint"), 16, data);
  ASSERT_EQ(shadowed.shadowed_lambertian_objects(), 1u);  // the floor; the pillow-shaped box is unoccluded
  shadowed.set_lighting(kLights);
  const Image image = frame(shadowed);
  // Prepared on another thread (as the kiosk does) and installed: the same frame, bit for bit.
  gpu::SceneRenderer async(scene, {}, methods::method("sgpoint"), 16, data);
  async.set_lighting(std::async(std::launch::async, [&] { return async.prepare_lighting(kLights); }).get());
  const Image async_image = frame(async);
  gpu::SceneRenderer open(scene, {}, methods::method("sgpoint"), 16, nullptr);
  EXPECT_EQ(open.shadowed_lambertian_objects(), 0u);
  open.set_lighting(kLights);
  const Image open_image = frame(open);

  // The C++ side: per-vertex irradiance (lambert_irradiance with SgVisibility), interpolated with
  // the pixel's barycentrics, × albedo/π.
  const SgVisibility at_axes = SgVisibility::compute(data->visibility.at(floor), mesh, kLights);
  std::vector<double> e(mesh.positions.size());
  for (size_t v = 0; v < e.size(); ++v)
    e[v] = lambert_irradiance(kLights, SurfaceFrame::from_normal_warp(mesh.normals[v], mesh.warps[v]), &at_axes, v,
                              &*data->kappa).r;
  const RayScene rays(scene);
  int compared = 0, darker = 0;
  double worst = 0;
  for (int y = 0; y < h; y += 2)
    for (int x = 0; x < w; x += 2) {
      EXPECT_EQ(image.at(x, y), async_image.at(x, y));
      const auto hit = rays.intersect(scene.camera.position, camera_ray(scene.camera, w, h, x + 0.5, y + 0.5));
      if (!hit || hit->object != floor) continue;
      const auto& tri = mesh.triangles[hit->triangle];
      const double b0 = 1 - hit->b1 - hit->b2;
      if (std::min({b0, hit->b1, hit->b2}) < 0.02) continue;  // triangle edges: either side may be drawn
      const double expected = 0.5 / kPi * (b0 * e[tri[0]] + hit->b1 * e[tri[1]] + hit->b2 * e[tri[2]]);
      const double got = image.at(x, y).r;
      worst = std::max(worst, std::abs(got - expected) / std::max(expected, 1e-3));
      darker += got < 0.9 * open_image.at(x, y).r;
      ++compared;
    }
  std::printf("floor pixels %d: worst relative difference %.2g, %d darker than the unshadowed floor\n", compared, worst,
              darker);
  ASSERT_GT(compared, 500);
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT(darker, 20);  // the shadow is in view: the unshadowed floor is brighter there
}
