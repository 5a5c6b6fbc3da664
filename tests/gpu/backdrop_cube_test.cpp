// The showroom backdrop's cube map (gpu/backdrop_cube.h) against the SG sum evaluated here in
// C++ along each pixel's camera ray: six cameras, one down each axis with a 100° view, so every
// face and its edges are looked up; the lighting is a softened environment (the sharpest lobe the
// backdrop ever shows, λ_b = 6) of lobes in arbitrary directions.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <cmath>
#include <cstdio>
#include <random>

#include "gl/offscreen_target.h"
#include "gpu/backdrop_cube.h"
#include "gpu/egl_context.h"
#include "gpu/scene_renderer.h"

using namespace weft;

TEST(BackdropCube, LookupMatchesTheSgSumOnEveryFace) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss;
  SgLighting sharp;
  for (double lambda : {2.0, 40.0, 1000.0, 0.5}) {
    SphericalGaussian g;
    g.axis = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
    g.sharpness = lambda;
    g.amplitude = glm::dvec3(1.0 + gauss(rng) * 0.2, 0.8, 0.6) * (lambda > 100 ? 50.0 : 1.0);
    sharp.push_back(g);
  }
  const SgLighting sgs = gpu::softened_environment(sharp);
  gpu::BackdropCube cube;
  cube.fill(sgs);
  const int w = 48, h = 48;
  gpu::OffscreenTarget target(w, h, /*full_float=*/true);
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  double worst = 0.0;
  for (const glm::vec3& look : axes) {
    const glm::vec3 up = std::abs(look.z) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    const glm::mat4 vp = glm::perspective(glm::radians(100.0f), 1.0f, 0.1f, 10.0f) * glm::lookAt(glm::vec3(0), look, up);
    const glm::mat4 inv = glm::inverse(vp);
    target.bind();
    cube.draw(inv, w, h);
    const std::vector<float> px = target.read_rgba();
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const glm::vec2 ndc((x + 0.5f) / w * 2.0f - 1.0f, (y + 0.5f) / h * 2.0f - 1.0f);
        const glm::vec4 a = inv * glm::vec4(ndc, -1, 1), b = inv * glm::vec4(ndc, 1, 1);
        const glm::dvec3 d = glm::normalize(glm::dvec3(glm::vec3(b) / b.w - glm::vec3(a) / a.w));
        glm::dvec3 expect(0.0);
        for (const auto& g : sgs) expect += g.amplitude * std::exp(g.sharpness * (glm::dot(d, g.axis) - 1.0));
        for (int c = 0; c < 3; ++c) {
          const double got = px[(size_t(y) * w + x) * 4 + c], rel = std::abs(got - expect[c]) / expect[c];
          worst = std::max(worst, rel);
          ASSERT_LT(rel, 5e-3) << "look " << look.x << "," << look.y << "," << look.z << " pixel " << x << "," << y;
        }
      }
  }
  std::printf("worst relative error of the cube lookup: %.2e\n", worst);
}
