// The showroom backdrop (gpu::Backdrop::showroom) drawn headless through render_gpu_frame, as
// `weft render` draws it: every pixel off the cloth shows the softened environment (non-black,
// following the lighting, equal to the softened SGs along the pixel's ray), while the frame's
// cloth mask and the cloth's radiance are those of the bench's measuring frame.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/spherical_gaussian.h"
#include "frame/frame_inputs.h"
#include "frame/frame_render.h"
#include "gpu/scene_renderer.h"

using namespace weft;

namespace {

FrameInputs swatch() { return load_frame_inputs({WEFT_SOURCE_ASSETS, "swatch", "", "", ""}); }

SgLighting warm_sky() {
  return {{glm::normalize(glm::dvec3(0.3, -0.2, 1.0)), 12.0, glm::dvec3(3.0, 2.0, 1.0)},
          {glm::dvec3(0, 0, 1), 1.0, glm::dvec3(0.4, 0.5, 0.6)}};
}
SgLighting blue_side() {
  return {{glm::normalize(glm::dvec3(-1.0, 0.5, 0.2)), 4.0, glm::dvec3(0.2, 0.4, 2.5)},
          {glm::dvec3(0, 0, -1), 2.0, glm::dvec3(0.3, 0.1, 0.05)}};
}

// The ray through pixel (x, y) (row 0 at the top), from the camera as docs/design.md's renderer sets it up.
glm::dvec3 pixel_ray(const Camera& cam, int x, int y, int w, int h) {
  const glm::dmat4 proj = glm::perspective(glm::radians(cam.fov_deg), double(w) / h, 0.05, 100.0);
  const glm::dmat4 inv = glm::inverse(proj * glm::lookAt(cam.position, cam.target, cam.up));
  const glm::dvec2 ndc((x + 0.5) / w * 2 - 1, 1 - (y + 0.5) / h * 2);
  const glm::dvec4 a = inv * glm::dvec4(ndc, -1, 1), b = inv * glm::dvec4(ndc, 1, 1);
  return glm::normalize(glm::dvec3(b) / b.w - glm::dvec3(a) / a.w);
}

size_t count(const std::vector<bool>& m) { return size_t(std::count(m.begin(), m.end(), true)); }

}  // namespace

TEST(SoftenedEnvironment, KeepsEachLobesIntegralAndWidensIt) {
  const SgLighting sgs = {{glm::dvec3(0, 0, 1), 1000.0, glm::dvec3(5.0)}, {glm::dvec3(1, 0, 0), 2.0, glm::dvec3(1, 2, 3)}};
  const SgLighting soft = gpu::softened_environment(sgs, 6.0);
  ASSERT_EQ(soft.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    const double l = sgs[k].sharpness;
    EXPECT_NEAR(soft[k].sharpness, l * 6.0 / (l + 6.0), 1e-12);
    EXPECT_EQ(soft[k].axis, sgs[k].axis);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(soft[k].amplitude[c] * sg_sphere_integral(soft[k].sharpness), sgs[k].amplitude[c] * sg_sphere_integral(l),
                  1e-9 * sgs[k].amplitude[c]);
  }
  EXPECT_LT(soft[0].amplitude.r, 0.01 * sgs[0].amplitude.r);  // a sun becomes a soft glow
}

TEST(Backdrop, DrawnBehindEveryMethodFollowingTheEnvironment) {
  const FrameInputs in = swatch();
  const int w = 64, h = 48;
  for (const std::string method : {"sgpoint", "sheen", "thin"}) {
    const GpuFrame a = render_gpu_frame(in.scene, in.fabrics, warm_sky(), method, w, h, 0, nullptr, gpu::Backdrop::showroom);
    const GpuFrame b = render_gpu_frame(in.scene, in.fabrics, blue_side(), method, w, h, 0, nullptr, gpu::Backdrop::showroom);
    ASSERT_EQ(a.cloth.size(), a.image.pixels.size());
    const size_t cloth = count(a.cloth);
    ASSERT_GT(cloth, a.cloth.size() / 10) << method;
    ASSERT_LT(cloth, a.cloth.size() * 9 / 10) << method;
    size_t off = 0, black = 0, same = 0;
    for (size_t i = 0; i < a.cloth.size(); ++i) {
      if (a.cloth[i]) continue;
      ++off;
      black += a.image.pixels[i] == glm::dvec3(0.0);
      same += glm::length(a.image.pixels[i] - b.image.pixels[i]) < 1e-3 * glm::length(a.image.pixels[i]);
    }
    EXPECT_EQ(black, 0u) << method;
    EXPECT_EQ(same, 0u) << method << ": the backdrop does not follow the environment";
    // The top-left pixel is off the swatch: it shows the softened SGs along its ray.
    ASSERT_FALSE(a.cloth[0]) << method;
    const glm::dvec3 expect = evaluate(gpu::softened_environment(warm_sky()), pixel_ray(in.scene.camera, 0, 0, w, h));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.image.at(0, 0)[c], expect[c], 2e-3 * expect[c] + 1e-5) << method;
  }
}

TEST(Backdrop, ClothMaskAndClothRadianceAreTheMeasuringFrames) {
  const FrameInputs in = swatch();
  const int w = 64, h = 48;
  for (const std::string method : {"sgpoint", "mdfrot"}) {
    const GpuFrame shown = render_gpu_frame(in.scene, in.fabrics, warm_sky(), method, w, h, 0, nullptr, gpu::Backdrop::showroom);
    const GpuFrame measured = render_gpu_frame(in.scene, in.fabrics, warm_sky(), method, w, h, 0, nullptr, gpu::Backdrop::measure);
    EXPECT_EQ(shown.cloth, measured.cloth) << method;
    size_t differ = 0;
    for (size_t i = 0; i < shown.cloth.size(); ++i) {
      // The measuring frame is black off the cloth (nothing else in the swatch scene), so its
      // non-black pixels are exactly the mask.
      EXPECT_EQ(measured.cloth[i], measured.image.pixels[i] != glm::dvec3(0.0)) << method << " pixel " << i;
      if (shown.cloth[i]) differ += shown.image.pixels[i] != measured.image.pixels[i];
    }
    EXPECT_EQ(differ, 0u) << method << ": the backdrop changed cloth pixels";
  }
}
