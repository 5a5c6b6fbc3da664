// Convergence of the scene reference under doubling (label `slow`: about a minute on 2 cores).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/fabric.h"
#include "reference/scene_render.h"
#include "scene/scene_file.h"

using namespace weft;
using glm::dvec3;

static const std::filesystem::path kAssets = WEFT_SOURCE_ASSETS;

// Doubling the lighting resolution and the tangent samples changes a pillow render (cloth
// self-shadowing on a shadowed floor) by less than 2 % relative RMSE at the default settings.
TEST(ReferenceRenderSlow, DoublingChangesPillowLessThanTolerance) {
  const Scene scene = load_scene_preset("pillow", kAssets / "scenes");
  const Fabric linen = load_fabric_preset("linen_plain", kAssets / "fabrics");
  ReferenceLighting lighting;
  lighting.sgs = {SphericalGaussian{glm::normalize(dvec3(-0.45, -0.55, 0.70)), 40.0, {9.0, 8.6, 8.0}},
                  SphericalGaussian{glm::normalize(dvec3(0.70, -0.35, 0.62)), 12.0, {1.6, 1.7, 1.9}},
                  SphericalGaussian{dvec3(0, 0, 1), 2.0, {0.55, 0.6, 0.7}}};
  ReferenceRenderOptions opt;
  opt.width = 48;
  opt.height = 36;
  opt.check_convergence = false;
  const ReferenceRenderer renderer(scene, {{"linen_plain", linen}}, lighting, opt);
  const ReferenceRenderResult coarse = renderer.render(0), fine = renderer.render(1);
  double se = 0, sum = 0;
  size_t n = 0, cloth = 0;
  for (size_t i = 0; i < coarse.image.pixels.size(); ++i) {
    if (fine.kinds[i] == PixelKind::background) continue;
    const dvec3 d = coarse.image.pixels[i] - fine.image.pixels[i];
    se += glm::dot(d, d);
    sum += glm::length(fine.image.pixels[i]);
    ++n;
    cloth += fine.kinds[i] == PixelKind::cloth;
  }
  ASSERT_GT(cloth, 200u);  // the pillow fills a good part of the frame
  const double rel_rmse = std::sqrt(se / n) / (sum / n);
  EXPECT_LT(rel_rmse, 0.02);
  std::printf("pillow 48x36: relative RMSE level 0 vs 1 = %.4f over %zu pixels\n", rel_rmse, n);
  // The renderer's own subset check measures the same quantity.
  const ConvergenceReport report = renderer.convergence(coarse, 0);
  EXPECT_LT(report.relative_rmse, 0.02);
}
