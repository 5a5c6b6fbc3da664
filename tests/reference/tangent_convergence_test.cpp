// The reference's choice of tangent samples (reference/tangent_convergence.h): satin's 2.5° float
// under a low sun needs more than the minimum, and at the chosen N_j the whole image is within
// the tolerance of 2·N_j (rendered independently of the check subset); linen under a broad sky
// stays at the minimum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/fabric.h"
#include "reference/scene_render.h"
#include "reference/tangent_convergence.h"
#include "scene/scene_file.h"
#include "support/sky_direction.h"

using namespace weft;
using glm::dvec3;
using weft::test::at_elevation;

namespace {

const std::filesystem::path kAssets = WEFT_SOURCE_ASSETS;

// The pillow in one fabric at 40x30.
struct PillowCase {
  Scene scene;
  std::map<std::string, Fabric> fabrics;
  ReferenceRenderOptions options;
};

PillowCase pillow_in(const std::string& fabric) {
  PillowCase c{load_scene_preset("pillow", kAssets / "scenes"), {}, {}};
  for (auto& o : c.scene.objects)
    if (o.material == Material::cloth) o.fabric = fabric;
  c.fabrics.emplace(fabric, load_fabric_preset(fabric, kAssets / "fabrics"));
  c.options.width = 40, c.options.height = 30, c.options.sg_grid = 8, c.options.check_stride = 2;
  c.options.check_convergence = false;
  return c;
}

// sqrt(mean |x−y|²)/mean |y| over every cloth pixel of two whole renders.
double cloth_change(const ReferenceRenderResult& x, const ReferenceRenderResult& y, size_t* pixels) {
  double se = 0, sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < x.image.pixels.size(); ++i) {
    if (y.kinds[i] != PixelKind::cloth) continue;
    const dvec3 d = x.image.pixels[i] - y.image.pixels[i];
    se += glm::dot(d, d);
    sum += glm::length(y.image.pixels[i]);
    ++n;
  }
  *pixels = n;
  return std::sqrt(se / n) / (sum / n);
}

}  // namespace

TEST(TangentConvergence, SatinUnderALowSunNeedsMoreThanTheMinimum) {
  PillowCase c = pillow_in("polyester_satin_charmeuse");
  ReferenceLighting lighting;
  // A sun 20° up to the pillow's side (+x; λ = 1000: about 2.6° wide) and a broad sky.
  lighting.sgs = {SphericalGaussian{at_elevation(0.0, 20.0), 1000.0, {400.0, 380.0, 340.0}},
                  SphericalGaussian{dvec3(0, 0, 1), 2.0, {0.5, 0.6, 0.8}}};
  TangentConvergenceOptions conv;
  conv.minimum = 16, conv.cap = 256, conv.tolerance = 0.01;
  const TangentConvergence choice = converge_tangent_samples(c.scene, c.fabrics, lighting, c.options, conv);
  for (const auto& s : choice.steps)
    std::printf("satin: %d vs %d: %.4f\n", s.samples, s.finer, s.relative_change);
  ASSERT_GT(choice.cloth_pixels, 50u);
  EXPECT_TRUE(choice.converged);
  EXPECT_GT(choice.samples, conv.minimum);
  EXPECT_GT(choice.steps.front().relative_change, conv.tolerance);

  ReferenceRenderOptions at = c.options;
  at.tangent_samples = choice.samples;
  const ReferenceRenderResult chosen = ReferenceRenderer(c.scene, c.fabrics, lighting, at).render(0);
  at.tangent_samples = 2 * choice.samples;
  const ReferenceRenderResult doubled = ReferenceRenderer(c.scene, c.fabrics, lighting, at).render(0);
  size_t pixels = 0;
  const double change = cloth_change(chosen, doubled, &pixels);
  std::printf("satin: N_j %d, whole image against %d: %.4f over %zu cloth pixels\n", choice.samples,
              2 * choice.samples, change, pixels);
  EXPECT_LE(change, conv.tolerance);
}

TEST(TangentConvergence, LinenUnderABroadSkyKeepsTheMinimum) {
  PillowCase c = pillow_in("linen_plain");
  ReferenceLighting lighting;
  lighting.sgs = {SphericalGaussian{dvec3(0, 0, 1), 2.0, {0.5, 0.6, 0.8}},
                  SphericalGaussian{at_elevation(-60.0, 30.0), 4.0, {0.8, 0.7, 0.6}}};
  TangentConvergenceOptions conv;
  conv.minimum = 16, conv.cap = 256, conv.tolerance = 0.01;
  const TangentConvergence choice = converge_tangent_samples(c.scene, c.fabrics, lighting, c.options, conv);
  ASSERT_EQ(choice.steps.size(), 1u);
  std::printf("linen: %d vs %d: %.4f\n", choice.steps[0].samples, choice.steps[0].finer, choice.steps[0].relative_change);
  EXPECT_TRUE(choice.converged);
  EXPECT_EQ(choice.samples, conv.minimum);
  EXPECT_LE(choice.steps[0].relative_change, conv.tolerance);
}

TEST(TangentConvergence, RejectsBadSettings) {
  PillowCase c = pillow_in("linen_plain");
  ReferenceLighting lighting;
  lighting.sgs = {SphericalGaussian{dvec3(0, 0, 1), 2.0, {1.0, 1.0, 1.0}}};
  TangentConvergenceOptions conv;
  conv.minimum = 64, conv.cap = 32;
  EXPECT_THROW(converge_tangent_samples(c.scene, c.fabrics, lighting, c.options, conv), std::invalid_argument);
  conv.minimum = 16, conv.cap = 256, conv.tolerance = 0.0;
  EXPECT_THROW(converge_tangent_samples(c.scene, c.fabrics, lighting, c.options, conv), std::invalid_argument);
}
