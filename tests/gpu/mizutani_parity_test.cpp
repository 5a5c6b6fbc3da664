// Parity: methods/mizutani/mizutani.glsl, run on the GL driver (llvmpipe here) and read back, agrees
// with the C++ twin render/methods/mizutani/mizutani.cpp within 1e-3 relative, per pixel, with the
// tables uploaded by methods/mizutani/mizutani_textures (so the upload layout is pinned too).
#include <gtest/gtest.h>

#include <random>

#include "bake/tables/azimuthal_bake.h"
#include "bake/tables/bake_selection.h"
#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "gpu/egl_context.h"
#include "methods/fabric_uniforms.h"
#include "gl/gl_program.h"
#include "methods/mizutani/mizutani_textures.h"
#include "methods/mizutani/mizutani.h"
#include "methods/registry.h"
#include "shaders/embedded_shaders.h"
#include "support/gpu_parity.h"

using namespace weft;
using namespace weft::gpu;

class MizutaniParity : public ::testing::TestWithParam<std::string> {};

TEST_P(MizutaniParity, GlslMatchesCpp) {
  EglContext ctx = EglContext::headless();
  const Fabric fabric = load_fabric_preset(GetParam(), WEFT_SOURCE_ASSETS "/fabrics");
  // Small tables: parity does not need accurate ones, only the same ones on both sides.
  BakeSettings s;
  s.tangent_samples = paper_tangent_samples(fabric);
  s.xi_resolution = s.wo_resolution = s.wi_resolution = 12;
  s.lambda_levels = 3;
  const WeightingTables tables = bake_weighting_tables(fabric, s);
  AzimuthalTableSettings as;
  as.quadrature_points = 256;
  const AzimuthalTable azimuthal = bake_azimuthal_table(as);
  const ClothBsdf bsdf(fabric, s.tangent_samples);

  std::string fs = shader_preamble() + "#define MAX_SGS " + std::to_string(kMizutaniMaxSgs) + "\n";
  for (auto part : methods::method("mizutani").glsl) fs += shaders::source(part);  // as the renderer builds it
  GlProgram program(fullscreen_triangle_vs(), fs + test::frame_case_main("vec4(mizutani_radiance(n, u, wo), 1.0)"));
  upload_fabric(program, bsdf);
  const MizutaniTextures textures(tables, azimuthal);
  textures.bind(program, 3);
  // Broad to sharp lights, past the tables' λ range on both sides, one below the horizon.
  const SgLighting sgs = {{glm::normalize(dvec3(-0.3, 0.1, 0.9)), 2.0, dvec3(1.0, 0.8, 0.6)},
                          {glm::normalize(dvec3(0.6, -0.5, 0.5)), 60.0, dvec3(0.5, 0.4, 0.3)},
                          {glm::normalize(dvec3(0.1, 0.8, 0.3)), 3000.0, dvec3(2.0)},
                          {glm::normalize(dvec3(-0.7, -0.2, -0.1)), 8.0, dvec3(0.3)}};
  upload_mizutani_lights(program, sgs);

  const int w = 16, h = 8;
  std::mt19937 rng(5);
  std::normal_distribution<float> nd;
  std::vector<float> wo(w * h * 4), nn(w * h * 4), uu(w * h * 4);
  std::vector<SurfaceFrame> frames(w * h);
  for (int i = 0; i < w * h; ++i) {
    glm::vec3 n = glm::normalize(glm::vec3(0.3f * nd(rng), 0.3f * nd(rng), 1.0f));
    glm::vec3 warp(nd(rng), nd(rng), nd(rng));
    glm::vec3 u = glm::normalize(warp - glm::dot(warp, n) * n);
    glm::vec3 d;
    do d = glm::normalize(glm::vec3(nd(rng), nd(rng), nd(rng)));
    while (glm::dot(d, n) <= 0.1f);
    test::store_direction(wo, i, d), test::store_direction(nn, i, n), test::store_direction(uu, i, u);
    frames[i].n = glm::dvec3(n);
    frames[i].u = glm::dvec3(u);
    frames[i].v = glm::cross(frames[i].n, frames[i].u);
  }
  const auto px = test::shade_cases(program, w, h, {{"u_wo", &wo}, {"u_n", &nn}, {"u_u", &uu}});

  double worst = 0.0, typical = 0.0;
  std::vector<dvec3> expect(w * h);
  for (int i = 0; i < w * h; ++i) {
    expect[i] = mizutani_radiance(bsdf, tables, azimuthal, frames[i], dvec3(wo[4 * i], wo[4 * i + 1], wo[4 * i + 2]), sgs)
                    .radiance;
    typical = std::max(typical, expect[i].g);
  }
  ASSERT_GT(typical, 0.0);
  for (int i = 0; i < w * h; ++i)
    for (int c = 0; c < 3; ++c) {
      const double got = px[4 * i + c];
      ASSERT_TRUE(std::isfinite(got));
      // Relative where the value matters; an absolute floor at 1e-4 of the brightest pixel.
      const double err = std::abs(got - expect[i][c]) / std::max(std::abs(expect[i][c]), 1e-4 * typical);
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-3) << GetParam() << " pixel " << i << " channel " << c << ": glsl " << got << " c++ "
                           << expect[i][c];
    }
  std::printf("%s: %d values, worst relative difference %.2e\n", GetParam().c_str(), 3 * w * h, worst);
}

INSTANTIATE_TEST_SUITE_P(Presets, MizutaniParity,
                         ::testing::Values("linen_plain", "silk_crepe_de_chine", "polyester_satin_charmeuse"));
