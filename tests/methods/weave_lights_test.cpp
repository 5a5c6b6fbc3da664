// The weave layer's lights (methods/weave/weave_lights.h). The split of a broad lobe must light a
// surface as the lobe does: its irradiance on planes of every orientation against the SG's own,
// both by quadrature over the sphere. Each vertex's visibility of each light, from the bake's mask
// and from its SDF, against the open share of the light found by casting rays through its lobe.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include "bake/visibility/scene_visibility.h"
#include "bake/visibility/visibility_mask_bake.h"
#include "methods/sg_lights.h"
#include "methods/weave/weave_lights.h"
#include "reference/ray_scene.h"
#include "scene/scene_file.h"

using namespace weft;
using glm::dvec3;

namespace {

// ∫ G(ω) f(ω) dω over the sphere on an n × 2n grid in (cos θ, φ) (equal area per cell).
template <class F>
dvec3 sphere_integral(const SphericalGaussian& g, F f, int n = 400) {
  dvec3 sum(0.0);
  const double cell = 4.0 * std::numbers::pi / (2.0 * n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double z = -1.0 + 2.0 * (i + 0.5) / n, r = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = std::numbers::pi * (j + 0.5) / n;
      const dvec3 w(r * std::cos(phi), r * std::sin(phi), z);
      sum += g.amplitude * std::exp(g.sharpness * (glm::dot(w, g.axis) - 1.0)) * f(w) * cell;
    }
  return sum;
}

}  // namespace

TEST(WeaveLights, SplitLobesLightEveryPlaneAsTheLobeDoes) {
  const SgLighting sgs = {SphericalGaussian{glm::normalize(dvec3(0.2, -0.3, 0.9)), 1.0, {2.0, 1.8, 1.5}},
                          SphericalGaussian{glm::normalize(dvec3(-0.7, 0.1, 0.3)), 3.0, {0.5, 0.6, 0.7}},
                          SphericalGaussian{glm::normalize(dvec3(0.5, 0.5, 0.5)), 120.0, {4.0, 4.0, 3.0}}};
  const SgLighting lights = weave_lights(sgs, 40);
  ASSERT_EQ(lights.size(), 3u + 2u * (kWeaveSplitParts - 1));  // the two broad lobes split, the sharp one kept
  int sharp_kept = 0;
  for (const auto& l : lights) sharp_kept += l.sharpness == 120.0 && l.axis == sgs[2].axis && l.amplitude == sgs[2].amplitude;
  EXPECT_EQ(sharp_kept, 1);
  dvec3 power(0.0), split_power(0.0);
  for (const auto& g : sgs) power += sg_power(g);
  for (const auto& l : lights) split_power += sg_power(l);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(split_power[c], power[c], 1e-9 * power[c]);
  // Irradiance E(n) = ∫ L max(n·ω, 0) dω on planes facing every way, against the lighting's own.
  std::mt19937 rng(5);
  std::normal_distribution<double> gauss;
  double worst = 0.0;
  for (int trial = 0; trial < 40; ++trial) {
    const dvec3 n = glm::normalize(dvec3(gauss(rng), gauss(rng), gauss(rng)));
    auto cosine = [&](const dvec3& w) { return std::max(glm::dot(n, w), 0.0); };
    dvec3 e(0.0), e_split(0.0);
    for (const auto& g : sgs) e += sphere_integral(g, cosine);
    for (const auto& l : lights) e_split += sphere_integral(l, cosine);
    worst = std::max(worst, std::abs(e_split.g - e.g) / (e.g + 0.05 * power.g));
  }
  std::cout << "split lobes: worst irradiance difference " << worst << " (of E + 5 % of the power)\n";
  EXPECT_LT(worst, 0.05);
}

TEST(WeaveLights, AFullLightingKeepsWithinTheShadersLimit) {
  SgLighting sgs;
  for (int k = 0; k < 10; ++k) sgs.push_back({glm::normalize(dvec3(std::cos(k), std::sin(k), 0.5)), 0.4 + 0.3 * k, dvec3(1.0)});
  const SgLighting lights = weave_lights(sgs, 24);
  EXPECT_LE(lights.size(), 24u);
  // Ten broad lobes; the broadest split first: λ = 0.4, 0.7, 1.0 split (10 + 3·4 = 22), a fourth would make 26.
  EXPECT_EQ(lights.size(), 22u);
  int whole_broadest = 0;
  for (const auto& l : lights) whole_broadest += l.sharpness == 0.4;
  EXPECT_EQ(whole_broadest, 0);
}

TEST(WeaveLights, VertexVisibilityMatchesRaysThroughEachLobe) {
  const Scene scene = load_scene_preset("pillow", WEFT_SOURCE_ASSETS "/scenes");
  size_t cloth = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].material == Material::cloth) cloth = i;
  const TriangleMesh& mesh = scene.objects[cloth].mesh;
  const std::optional<VisibilityMask> mask = bake_visibility_mask(scene, cloth, kMaskResolution);
  SceneVisibilityOptions vo;
  vo.resolution = 64;
  const std::optional<ObjectVisibility> sdf = bake_object_visibility(scene, cloth, vo);
  ASSERT_TRUE(mask && sdf);
  // Lobes from overhead to grazing: the pillow's own curve and the floor block the low ones.
  SgLighting lights;
  for (const dvec3& a : {dvec3(0, 0, 1), dvec3(0.6, -0.2, 0.35), dvec3(-0.8, 0.3, 0.12), dvec3(0.1, 0.95, 0.05)})
    for (double lambda : {8.0, 60.0}) lights.push_back({glm::normalize(a), lambda, dvec3(1.0)});
  const std::vector<float> from_mask = weave_light_visibility(&*mask, nullptr, mesh, lights);
  const std::vector<float> from_sdf = weave_light_visibility(nullptr, &*sdf, mesh, lights);
  EXPECT_TRUE(weave_light_visibility(nullptr, nullptr, mesh, lights).empty());
  ASSERT_EQ(from_mask.size(), mesh.positions.size() * lights.size());
  ASSERT_EQ(from_sdf.size(), from_mask.size());
  // The open share of light k's part above vertex v's surface: rays drawn from the lobe (its
  // exact inverse CDF in cos θ, a golden-angle spiral in φ), those above the surface counted.
  const RayScene rays(scene);
  auto traced = [&](size_t v, const SphericalGaussian& g) {
    const dvec3 n = glm::normalize(mesh.normals[v]), origin = mesh.positions[v] + n * rays.ray_epsilon();
    const dvec3 e1 = glm::normalize(glm::cross(g.axis, std::abs(g.axis.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    const dvec3 e2 = glm::cross(g.axis, e1);
    int open = 0, above = 0;
    constexpr int kRays = 512;
    for (int i = 0; i < kRays; ++i) {
      const double u = (i + 0.5) / kRays, phi = 2.399963229728653 * i;
      const double c = 1.0 + std::log(1.0 - u * (1.0 - std::exp(-2.0 * g.sharpness))) / g.sharpness;
      const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
      const dvec3 d = c * g.axis + s * (std::cos(phi) * e1 + std::sin(phi) * e2);
      if (glm::dot(d, n) <= 0.0) continue;
      ++above;
      open += rays.unoccluded(origin, d);
    }
    return above > 0 ? double(open) / above : 1.0;
  };
  // Each pair weighted by the light's share above the surface, Φ(√λ·elevation): a lobe almost
  // wholly below the horizon lights nothing, whatever share of its tail is open.
  double mask_error = 0.0, sdf_error = 0.0, shadowed = 0.0, weight = 0.0;
  for (size_t v = 0; v < mesh.positions.size(); v += 23)
    for (size_t k = 0; k < lights.size(); ++k) {
      const double e = std::asin(std::clamp(glm::dot(glm::normalize(mesh.normals[v]), lights[k].axis), -1.0, 1.0));
      const double above = 0.5 * std::erfc(-std::sqrt(lights[k].sharpness) * e / std::numbers::sqrt2);
      const double want = traced(v, lights[k]);
      mask_error += above * std::abs(from_mask[v * lights.size() + k] - want);
      sdf_error += above * std::abs(from_sdf[v * lights.size() + k] - want);
      shadowed += above * (1.0 - want);
      weight += above;
    }
  std::cout << "weighted mean blocked share " << shadowed / weight << "; weighted mean |error| from the mask "
            << mask_error / weight << ", from the SDF " << sdf_error / weight << "\n";
  EXPECT_GT(shadowed / weight, 0.05);  // the case has shadows to get right
  EXPECT_LT(mask_error / weight, 0.02);
  EXPECT_LT(sdf_error / weight, 0.1);
}
