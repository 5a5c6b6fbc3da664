// The scene reference renderer against independent expectations: `weft eval`'s converged
// quadrature at swatch pixels, Lambertian closed forms, a shadow cast by an occluder, power
// conservation of the map's directional samples, and convergence under doubling.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/cloth_bsdf.h"
#include "core/fabric.h"
#include "lighting/env_map.h"
#include "reference/environment_samples.h"
#include "reference/scene_render.h"
#include "reference/sg_quadrature.h"
#include "scene/scene_file.h"

using namespace weft;
using glm::dvec3;

static const std::filesystem::path kAssets = WEFT_SOURCE_ASSETS;

static SgLighting test_sgs() {
  return {SphericalGaussian{glm::normalize(dvec3(-0.45, -0.55, 0.70)), 40.0, {9.0, 8.6, 8.0}},
          SphericalGaussian{glm::normalize(dvec3(0.70, -0.35, 0.62)), 12.0, {1.6, 1.7, 1.9}},
          SphericalGaussian{dvec3(0, 0, 1), 2.0, {0.55, 0.6, 0.7}}};
}

static double relative_difference(const dvec3& a, const dvec3& b) { return glm::length(a - b) / glm::length(b); }

TEST(ReferenceRender, SwatchPixelsMatchEval) {
  const Scene scene = load_scene_preset("swatch", kAssets / "scenes");
  const Fabric linen = load_fabric_preset("linen_plain", kAssets / "fabrics");
  ReferenceLighting lighting;
  lighting.sgs = test_sgs();
  ReferenceRenderOptions opt;
  opt.width = 48;
  opt.height = 36;
  opt.sg_grid = 8;
  opt.tangent_samples = 16;
  const ReferenceRenderer renderer(scene, {{"linen_plain", linen}}, lighting, opt);
  // The `weft eval` path: flat swatch frame n = +z, warp +x, adaptive converged quadrature.
  const ClothBsdf bsdf(linen, 16);
  SgQuadratureOptions eval;
  eval.min_polar = 32;
  eval.tolerance = 0.002;
  for (auto [x, y] : {std::pair{24, 18}, std::pair{14, 24}, std::pair{33, 12}}) {
    PixelKind kind;
    const dvec3 rendered = renderer.pixel(x, y, 0, &kind);
    ASSERT_EQ(kind, PixelKind::cloth) << x << "," << y;
    const dvec3 wo = -camera_ray(scene.camera, opt.width, opt.height, x + 0.5, y + 0.5);
    const SgQuadratureResult expect = integrate_sg_lighting(bsdf, SurfaceFrame{}, wo, lighting.sgs, eval);
    ASSERT_TRUE(expect.converged);
    EXPECT_LT(relative_difference(rendered, expect.radiance), 0.01)
        << x << "," << y << ": rendered " << rendered.r << " " << rendered.g << " " << rendered.b << " eval "
        << expect.radiance.r << " " << expect.radiance.g << " " << expect.radiance.b;
  }
  // A corner pixel sees the background: the SG lighting along the ray.
  PixelKind kind;
  const dvec3 corner = renderer.pixel(0, 0, 0, &kind);
  EXPECT_EQ(kind, PixelKind::background);
  EXPECT_EQ(corner, dvec3(0.0));  // no background function given: black
}

// ∫_{H} μ e^{λ(cos θ − 1)} (albedo/π) cos θ dω with the SG on the normal:
//   2 μ albedo (1/λ − (1 − e^{−λ})/λ²).
TEST(ReferenceRender, LambertianSgQuadratureMatchesClosedForm) {
  const dvec3 mu(1, 2, 3), albedo(0.5, 0.25, 1.0);
  for (double lambda : {0.5, 5.0, 200.0}) {
    const SphericalGaussian g{dvec3(0, 0, 1), lambda, mu};
    // The hemisphere's edge cuts through grid cells: first-order convergence in the grid.
    SgQuadratureOptions opt;
    opt.fixed_polar = 128;
    const dvec3 got = integrate_sg_lambertian(dvec3(0, 0, 1), albedo, std::span(&g, 1), opt).radiance;
    const dvec3 expect = 2.0 * mu * albedo * (1.0 / lambda - -std::expm1(-lambda) / (lambda * lambda));
    EXPECT_LT(relative_difference(got, expect), 1e-3) << "λ = " << lambda;
    const SgQuadratureResult adaptive = integrate_sg_lambertian(dvec3(0, 0, 1), albedo, std::span(&g, 1));
    EXPECT_TRUE(adaptive.converged);
    EXPECT_LT(relative_difference(adaptive.radiance, expect), 2e-3) << "λ = " << lambda;
  }
  // Tilted 70° off the normal: the hemisphere cut matters; compare with a dense (θ, φ) grid.
  const SphericalGaussian g{dvec3(std::sin(1.22), 0, std::cos(1.22)), 3.0, dvec3(1.0)};
  SgQuadratureOptions opt;
  opt.fixed_polar = 128;
  const double got = integrate_sg_lambertian(dvec3(0, 0, 1), dvec3(1.0), std::span(&g, 1), opt).radiance.r;
  double brute = 0;
  const int n = 800;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 2 * n; ++k) {
      const double t = (i + 0.5) / n * std::numbers::pi / 2, p = (k + 0.5) / (2 * n) * 2 * std::numbers::pi;
      const dvec3 w(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
      brute += g(w).r * std::cos(t) / std::numbers::pi * std::sin(t);
    }
  brute *= (std::numbers::pi / 2 / n) * (std::numbers::pi / n);
  EXPECT_NEAR(got, brute, 2e-3 * brute);
}

static Scene shadow_scene() {
  return parse_scene(R"({
    "name": "shadow", "environment": "studio",
    "camera": {"position": [0, -2, 1.5], "target": [0, 0.3, 0], "up": [0, 0, 1], "fov_deg": 40},
    "objects": [
      {"name": "floor", "material": "lambertian", "albedo": [0.5, 0.5, 0.5],
       "mesh": {"generator": "quad", "size_x": 20, "size_y": 20}},
      {"name": "blocker", "material": "lambertian", "albedo": [0.5, 0.5, 0.5],
       "mesh": {"generator": "quad", "size_x": 0.4, "size_y": 0.4, "translate": [0, 0.3, 0.5]}}]})",
                     "shadow.json", kAssets / "scenes");
}

// The shadow scene at 41×31 under an overhead sun (λ 200, unit amplitude), and the floor's
// radiance where that sun reaches it: albedo/π · the SG's clamped-cosine integral (closed form).
ReferenceRenderOptions shadow_scene_options(bool occlusion) {
  ReferenceRenderOptions opt;
  opt.width = 41, opt.height = 31, opt.occlusion = occlusion;
  return opt;
}
ReferenceLighting overhead_sun() {
  ReferenceLighting lighting;
  lighting.sgs = {SphericalGaussian{dvec3(0, 0, 1), 200.0, dvec3(1.0)}};
  return lighting;
}
const double kSunlitFloor = 2.0 * 0.5 * (1.0 / 200.0 - -std::expm1(-200.0) / (200.0 * 200.0));

TEST(ReferenceRender, OccluderCastsShadowOnLambertianFloor) {
  const Scene scene = shadow_scene();
  const ReferenceRenderOptions opt = shadow_scene_options(true);
  const ReferenceRenderer renderer(scene, {}, overhead_sun(), opt);
  const double lit = kSunlitFloor;
  PixelKind kind;
  // The centre ray hits the floor at (0, 0.3, 0), straight under the blocker.
  const dvec3 shadowed = renderer.pixel(20, 15, 0, &kind);
  EXPECT_EQ(kind, PixelKind::lambertian);
  EXPECT_LT(shadowed.r, 1e-3 * lit);
  // Near the left edge the floor is far from the blocker's shadow.
  const dvec3 open = renderer.pixel(1, 28, 0, &kind);
  EXPECT_EQ(kind, PixelKind::lambertian);
  EXPECT_NEAR(open.r, lit, 2e-3 * lit);
  // The same with the sun as a map's directional sample of equal power.
  ReferenceLighting as_samples;
  const double power = 2 * std::numbers::pi / 200.0 * -std::expm1(-400.0);
  as_samples.samples = [&](int) { return std::vector<DirectionalSample>{{dvec3(0, 0, 1), dvec3(power)}}; };
  const ReferenceRenderer sampled(scene, {}, as_samples, opt);
  EXPECT_LT(sampled.pixel(20, 15, 0).r, 1e-12);
  EXPECT_NEAR(sampled.pixel(1, 28, 0).r, power * 0.5 / std::numbers::pi, 1e-9);
}

TEST(ReferenceRender, WithoutOcclusionOnlyTheHorizonCutsTheLight) {
  const Scene scene = shadow_scene();
  const ReferenceRenderOptions opt = shadow_scene_options(false);
  const ReferenceRenderer renderer(scene, {}, overhead_sun(), opt);
  const double lit = kSunlitFloor;
  // Straight under the blocker the floor is lit as if it were not there.
  EXPECT_NEAR(renderer.pixel(20, 15, 0).r, lit, 2e-3 * lit);
  // A sun below the floor still leaves it dark: the surface's own horizon stays.
  ReferenceLighting below_floor;
  below_floor.sgs = {{dvec3(0, 0, -1), 200.0, dvec3(1.0)}};
  const ReferenceRenderer below(scene, {}, below_floor, opt);
  EXPECT_LT(below.pixel(20, 15, 0).r, 1e-6 * lit);
}

TEST(ReferenceRender, EnvironmentSamplesKeepThePowerOfTheMap) {
  EnvMapRepairs repairs;
  const EnvMap map = load_env_map(kAssets / "envmaps" / "studio.exr", NonFinitePolicy::clamp, &repairs);
  const dvec3 total = 4.0 * std::numbers::pi * mean_radiance(map);
  for (int width : {32, 64, 128}) {
    const auto samples = environment_samples(map, width);
    EXPECT_LE(samples.size(), size_t(width * width / 2));
    dvec3 sum(0.0);
    for (const auto& s : samples) {
      sum += s.power;
      EXPECT_NEAR(glm::length(s.direction), 1.0, 1e-12);
    }
    EXPECT_LT(relative_difference(sum, total), 1e-6) << width;
  }
}

