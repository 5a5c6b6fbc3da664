// Parity: shaders/microcylinder.glsl, run on the GL driver (llvmpipe here) and read back,
// agrees with the canonical C++ model (render/core) within 1e-3 relative, on every preset.
#include <gtest/gtest.h>

#include <random>

#include "core/cloth_bsdf.h"
#include "gpu/egl_context.h"
#include "methods/fabric_uniforms.h"
#include "gl/gl_program.h"
#include "shaders/embedded_shaders.h"
#include "support/gpu_parity.h"

using namespace weft;
using namespace weft::gpu;

namespace {

// One (ω_i, ω_o, frame) per pixel, from float textures, so both sides see the same floats.
const char* kFs = R"(
uniform highp sampler2D u_wi, u_wo, u_n, u_u;
out vec4 colour;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 wi = texelFetch(u_wi, p, 0).xyz, wo = texelFetch(u_wo, p, 0).xyz;
  vec3 n = texelFetch(u_n, p, 0).xyz, u = texelFetch(u_u, p, 0).xyz;
  colour = vec4(cloth_integrand(n, u, wi, wo), 1.0);
})";

}  // namespace

class MicrocylinderParity : public ::testing::TestWithParam<std::string> {};

TEST_P(MicrocylinderParity, GlslMatchesCanonicalModel) {
  EglContext ctx = EglContext::headless();
  const Fabric fabric = load_fabric_preset(GetParam(), WEFT_SOURCE_ASSETS "/fabrics");
  const ClothBsdf bsdf(fabric, 16);
  GlProgram program(fullscreen_triangle_vs(), shader_preamble() + std::string(shaders::source("microcylinder.glsl")) + kFs);
  upload_fabric(program, bsdf);

  const int w = 32, h = 16;
  std::mt19937 rng(11);
  std::normal_distribution<float> nd;
  std::vector<float> wi(w * h * 4), wo(w * h * 4), nn(w * h * 4), uu(w * h * 4);
  std::vector<SurfaceFrame> frames(w * h);
  for (int i = 0; i < w * h; ++i) {
    // A tilted shading frame per pixel (as on a mesh), and directions at least ~6° above it.
    glm::vec3 n = glm::normalize(glm::vec3(0.3f * nd(rng), 0.3f * nd(rng), 1.0f));
    glm::vec3 warp(nd(rng), nd(rng), nd(rng));
    glm::vec3 u = glm::normalize(warp - glm::dot(warp, n) * n);
    auto above = [&] {
      for (;;) {
        glm::vec3 d = glm::normalize(glm::vec3(nd(rng), nd(rng), nd(rng)));
        if (glm::dot(d, n) > 0.1f) return d;
      }
    };
    const glm::vec3 a = above(), b = above();
    test::store_direction(wi, i, a), test::store_direction(wo, i, b), test::store_direction(nn, i, n), test::store_direction(uu, i, u);
    frames[i].n = glm::dvec3(n);
    frames[i].u = glm::dvec3(u);
    frames[i].v = glm::cross(frames[i].n, frames[i].u);
  }
  const auto px = test::shade_cases(program, w, h, {{"u_wi", &wi}, {"u_wo", &wo}, {"u_n", &nn}, {"u_u", &uu}});

  double worst = 0.0;
  int compared = 0;
  for (int i = 0; i < w * h; ++i) {
    auto point = bsdf.at(frames[i]);
    const dvec3 expect =
        point.integrand(dvec3(wi[4 * i], wi[4 * i + 1], wi[4 * i + 2]), dvec3(wo[4 * i], wo[4 * i + 1], wo[4 * i + 2]));
    for (int c = 0; c < 3; ++c) {
      const double got = px[4 * i + c];
      ASSERT_TRUE(std::isfinite(got));
      // Relative where the value matters; an absolute floor for values ~1e-6 of a typical one.
      const double err = std::abs(got - expect[c]) / std::max(std::abs(expect[c]), 1e-4);
      worst = std::max(worst, err);
      ++compared;
      EXPECT_LT(err, 1e-3) << GetParam() << " pixel " << i << " channel " << c << ": glsl " << got << " c++ "
                           << expect[c];
    }
  }
  std::printf("%s: %d values, worst relative difference %.2e\n", GetParam().c_str(), compared, worst);
}

INSTANTIATE_TEST_SUITE_P(Presets, MicrocylinderParity,
                         ::testing::Values("linen_plain", "silk_crepe_de_chine", "polyester_satin_charmeuse",
                                           "polyester_satin_charmeuse_back", "silk_shot", "velvet"));
