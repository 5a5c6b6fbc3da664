// Parity of the SG-lit runtime methods: shaders/{sg_lighting,sheen,mdfrot,thin}.glsl run on
// the GL driver (llvmpipe here) and read back agree with render/methods' C++ within 1e-3
// relative (values below 1e-3 of the case's mean compared absolutely at that scale), on every
// preset, for random frames, views and a fixed set of SGs whose sharpness spans both branches
// of the irradiance fit (λ from 0.2 to 500).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>

#include "core/cloth_bsdf.h"
#include "core/fabric.h"
#include "gpu/egl_context.h"
#include "methods/fabric_uniforms.h"
#include "gl/gl_program.h"
#include "methods/mdfrot/mdfrot_method.h"
#include "methods/registry.h"
#include "methods/sg_lighting_uniforms.h"
#include "methods/sheen/sheen_method.h"
#include "methods/thin/thin_method.h"
#include "shaders/embedded_shaders.h"
#include "support/gpu_parity.h"
#include "support/strict_glsl.h"

using namespace weft;
using namespace weft::gpu;

namespace {

SgLighting test_sgs() {
  std::mt19937 rng(5);
  std::normal_distribution<double> nd;
  std::uniform_real_distribution<double> ud(0.0, 1.0);
  SgLighting sgs;
  for (int k = 0; k < 8; ++k) {
    SphericalGaussian g;
    g.axis = glm::normalize(dvec3(nd(rng), nd(rng), nd(rng)));
    g.sharpness = 0.2 * std::pow(2500.0, k / 7.0);  // 0.2 … 500
    g.amplitude = dvec3(0.2 + ud(rng), 0.2 + ud(rng), 0.2 + ud(rng));
    sgs.push_back(g);
  }
  return sgs;
}

}  // namespace

class MethodParity : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(MethodParity, GlslMatchesCpp) {
  const auto& [method, preset] = GetParam();
  EglContext ctx = EglContext::headless();
  const Fabric fabric = load_fabric_preset(preset, WEFT_SOURCE_ASSETS "/fabrics");
  const ClothBsdf bsdf(fabric, 16);
  const SheenParams sheen = sheen_params(fabric);
  const MdfrotParams mdfrot = mdfrot_params(fabric);
  const ThinParams thin = thin_params(fabric);
  const SgLighting sgs = test_sgs();

  // The method's GLSL as the renderer builds it (the registry's parts), with a main of our own.
  const std::vector<std::string_view>& parts = methods::method(method).glsl;
  std::string call;
  if (method == "sheen") call = "vec4(sheen_radiance(n, wo, sheen_diffuse(vec3(1.0), vec3(1.0))), 1.0)";
  else if (method == "mdfrot") call = "vec4(mdfrot_radiance(n, u, wo), 1.0)";
  else call = "thin_radiance(n, u, wo)";
  std::string fs = shader_preamble();
  for (auto p : parts) fs += shaders::source(p);
  GlProgram program(fullscreen_triangle_vs(), fs + test::frame_case_main(call));
  upload_sg_lighting(program, sgs);
  if (method == "sheen") upload_sheen(program, sheen);
  if (method == "mdfrot") upload_mdfrot(program, mdfrot);
  if (method == "thin") upload_fabric(program, bsdf), upload_thin(program, thin);

  const int w = 32, h = 16;
  std::mt19937 rng(17);
  std::normal_distribution<float> nd;
  std::vector<float> wo(w * h * 4), nn(w * h * 4), uu(w * h * 4);
  for (int i = 0; i < w * h; ++i) {
    glm::vec3 n = glm::normalize(glm::vec3(0.3f * nd(rng), 0.3f * nd(rng), 1.0f));
    glm::vec3 warp(nd(rng), nd(rng), nd(rng));
    glm::vec3 u = glm::normalize(warp - glm::dot(warp, n) * n);
    glm::vec3 d;
    do d = glm::normalize(glm::vec3(nd(rng), nd(rng), nd(rng)));
    while (glm::dot(d, n) < 0.1f && method != "thin");  // thin also shades from behind
    if (method == "thin" && std::abs(glm::dot(d, n)) < 0.1f) d = glm::normalize(d + 0.2f * n);
    test::store_direction(wo, i, d), test::store_direction(nn, i, n), test::store_direction(uu, i, u);
  }
  const auto px = test::shade_cases(program, w, h, {{"u_wo", &wo}, {"u_n", &nn}, {"u_u", &uu}});

  std::vector<glm::dvec4> expect(w * h);
  double mean = 0.0;
  for (int i = 0; i < w * h; ++i) {
    const dvec3 o(wo[4 * i], wo[4 * i + 1], wo[4 * i + 2]);
    SurfaceFrame f;
    f.n = dvec3(nn[4 * i], nn[4 * i + 1], nn[4 * i + 2]);
    f.u = dvec3(uu[4 * i], uu[4 * i + 1], uu[4 * i + 2]);
    f.v = glm::cross(f.n, f.u);
    if (method == "sheen") expect[i] = glm::dvec4(sheen_radiance(sheen, f.n, o, sgs), 1.0);
    else if (method == "mdfrot") expect[i] = glm::dvec4(mdfrot_radiance(mdfrot, f, o, sgs), 1.0);
    else {
      const ThinShade s = thin_radiance(bsdf, thin, f, o, sgs);
      expect[i] = glm::dvec4(s.source, s.alpha);
    }
    mean += (expect[i].r + expect[i].g + expect[i].b) / (3.0 * w * h);
  }
  ASSERT_GT(mean, 0.0) << "the case lights nothing: it would test nothing";
  double worst = 0.0;
  for (int i = 0; i < w * h; ++i)
    for (int c = 0; c < 4; ++c) {
      const double got = px[4 * i + c];
      ASSERT_TRUE(std::isfinite(got));
      const double scale = c == 3 ? 1.0 : std::max(std::abs(expect[i][c]), 1e-3 * mean);
      const double err = std::abs(got - expect[i][c]) / scale;
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-3) << method << "/" << preset << " pixel " << i << " channel " << c << ": glsl " << got
                           << " c++ " << expect[i][c];
    }
  std::printf("%s/%s: worst relative difference %.2e (mean radiance %.3g)\n", method.c_str(), preset.c_str(), worst,
              mean);
}

INSTANTIATE_TEST_SUITE_P(
    MethodsByPreset, MethodParity,
    ::testing::Combine(::testing::Values("sheen", "mdfrot", "thin"),
                       ::testing::Values("linen_plain", "silk_crepe_de_chine", "polyester_satin_charmeuse",
                                         "polyester_satin_charmeuse_back", "silk_shot", "velvet")),
    [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });
