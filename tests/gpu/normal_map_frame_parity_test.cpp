// Parity: shaders/normal_map_frame.glsl on the GL driver agrees with core/normal_map_frame.h (the
// one source of the normal map's frame rotation) within float precision, on random frames, texels
// and scales.
#include <gtest/gtest.h>

#include <random>

#include "core/normal_map_frame.h"
#include "gl/gl_program.h"
#include "gpu/egl_context.h"
#include "shaders/embedded_shaders.h"
#include "support/gpu_parity.h"

using namespace weft;
using namespace weft::gpu;

namespace {
// u_texel's w carries the scale; `which` picks the output: 0 the turned n, 1 the turned u.
const char* kFs = R"(
uniform highp sampler2D u_n, u_u, u_texel;
uniform int u_which;
out vec4 colour;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 n = texelFetch(u_n, p, 0).xyz, u = texelFetch(u_u, p, 0).xyz;
  vec4 texel = texelFetch(u_texel, p, 0);
  normal_mapped_frame(n, u, tangent_space_normal(texel.rgb, texel.a));
  colour = vec4(u_which == 0 ? n : u, 1.0);
})";
}  // namespace

TEST(NormalMapFrameParity, GlslMatchesCpp) {
  EglContext ctx = EglContext::headless();
  GlProgram program(fullscreen_triangle_vs(), std::string("#version 300 es\nprecision highp float;\nprecision highp int;\n") + std::string(shaders::source("normal_map_frame.glsl")) + kFs);
  const int w = 32, h = 16;
  std::mt19937 rng(5);
  std::normal_distribution<float> nd;
  std::uniform_real_distribution<float> ud(0.0f, 1.0f);
  std::vector<float> nn(w * h * 4), uu(w * h * 4), texels(w * h * 4);
  for (int i = 0; i < w * h; ++i) {
    const glm::vec3 n = glm::normalize(glm::vec3(nd(rng), nd(rng), nd(rng)));
    const glm::vec3 warp(nd(rng), nd(rng), nd(rng));
    test::store_direction(nn, i, n);
    test::store_direction(uu, i, glm::normalize(warp - glm::dot(warp, n) * n));
    texels[4 * i] = ud(rng), texels[4 * i + 1] = ud(rng), texels[4 * i + 2] = ud(rng);
    texels[4 * i + 3] = 0.25f + 2.0f * ud(rng);
  }
  double worst = 0.0;
  for (int which = 0; which < 2; ++which) {
    program.use();
    glUniform1i(program.uniform("u_which"), which);
    const auto px = test::shade_cases(program, w, h, {{"u_n", &nn}, {"u_u", &uu}, {"u_texel", &texels}});
    for (int i = 0; i < w * h; ++i) {
      SurfaceFrame f;
      f.n = test::load_direction(nn, i);
      f.u = test::load_direction(uu, i);
      f.v = glm::cross(f.n, f.u);
      const dvec3 t = tangent_space_normal(dvec3(texels[4 * i], texels[4 * i + 1], texels[4 * i + 2]), texels[4 * i + 3]);
      const SurfaceFrame g = normal_mapped_frame(f, t);
      const dvec3 expect = which == 0 ? g.n : g.u;
      const double err = glm::length(dvec3(px[4 * i], px[4 * i + 1], px[4 * i + 2]) - expect);
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-4) << (which == 0 ? "n'" : "u'") << " case " << i;
    }
  }
  std::printf("normal map frame: worst |glsl − c++| %.2e\n", worst);
}
