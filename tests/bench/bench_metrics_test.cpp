// The bench's image measures against closed forms: masked_error on hand-computed pixels, and
// the sun's shadow mask of a square occluder (its shadow on a flat cloth is the square shifted
// by the sun's slant, seen from straight above: a known count of pixel centres).
#include <gtest/gtest.h>

#include <cmath>

#include "measure/image_metrics.h"
#include "bench/shadow_mask.h"
#include "scene/scene_file.h"

using namespace weft;
using glm::dvec3;

TEST(MaskedError, HandComputedPixels) {
  Image ref(2, 2), x(2, 2);
  ref.pixels = {dvec3(1.0), dvec3(3.0), dvec3(100.0), dvec3(7.0)};
  x.pixels = {dvec3(2.0), dvec3(3.0), dvec3(-50.0), dvec3(7.0)};
  const std::vector<bool> mask = {true, true, false, false};  // pixels 2 and 3 must not count
  const bench::MaskedError e = bench::masked_error(x, ref, mask);
  EXPECT_EQ(e.pixels, 2u);
  // sqrt(mean of squared differences over 2 pixels × 3 channels: (3·1 + 0)/6) / mean(r) = 2.
  EXPECT_NEAR(e.relative_rmse, std::sqrt(0.5) / 2.0, 1e-12);
  EXPECT_NEAR(e.brightness_ratio, 5.0 / 4.0, 1e-12);
  EXPECT_EQ(bench::masked_error(x, ref, {false, false, false, false}).pixels, 0u);
  EXPECT_THROW(bench::masked_error(x, ref, {true}), std::invalid_argument);
}

TEST(SunShadowMask, SquareOccluderSeenFromAbove) {
  // Cloth in z = 0; a 0.2 × 0.2 square at z = 0.5; sun along (0.6, 0, 0.8): the shadow is the
  // square shifted by 0.5·0.6/0.8 = 0.375 along −x. The camera looks straight down at the
  // shadow's centre from a height where one pixel spans 0.2/12 at the ground, so the shadow's
  // edges fall midway between pixel centres: 12 × 12 centres inside, and a 3-pixel band around
  // it holds 18² − 12² = 180.
  const int w = 160, h = 120;
  const double pixel = 0.2 / 12.0;
  const double height = pixel * h / (2.0 * std::tan(20.0 * std::acos(-1.0) / 180.0));
  const std::string json = R"({"name": "occluder", "camera": {"position": [-0.375, 0, )" + std::to_string(height) +
                           R"(], "target": [-0.375, 0, 0], "up": [0, 1, 0], "fov_deg": 40}, "environment": "studio",
    "objects": [
      {"name": "cloth", "material": "cloth", "fabric": "linen_plain", "mesh": {"generator": "swatch", "size": 4, "resolution": 4}},
      {"name": "square", "material": "lambertian", "albedo": [0.5, 0.5, 0.5],
       "mesh": {"generator": "quad", "size_x": 0.2, "size_y": 0.2, "translate": [0, 0, 0.5]}}]})";
  const Scene scene = parse_scene(json, "test", ".");
  const dvec3 sun_axis(0.6, 0.0, 0.8);
  // A broad, dimmer sky lobe: the mask follows the SG of highest peak radiance, not of most power.
  const SgLighting sgs = {SphericalGaussian{dvec3(0, 0, 1), 0.5, dvec3(20.0)},
                          SphericalGaussian{sun_axis, 1000.0, dvec3(50.0)}};
  const bench::ShadowMask m = bench::sun_shadow_mask(scene, sgs, w, h, 3);
  EXPECT_NEAR(glm::length(m.sun.axis - sun_axis), 0.0, 1e-12);
  ASSERT_EQ(m.shadow.size(), size_t(w * h));
  EXPECT_NEAR(double(m.shadow_pixels), 144.0, 4.0);  // perspective: a pixel off at most along an edge
  EXPECT_NEAR(double(m.band_pixels), 180.0, 8.0);
  // The shadow is centred in the frame: pixel rows and columns 54..65.
  for (int y = 56; y < 64; ++y)
    for (int x = 76; x < 84; ++x) EXPECT_TRUE(m.shadow[size_t(y) * w + x]) << x << "," << y;
  EXPECT_FALSE(m.shadow[size_t(60) * w + 60]);
}
