// Parity: methods/iwasaki/vertex_normal_map.glsl (the per-vertex rungs' normal-map ratio) on the GL
// driver against its C++ twin, methods/iwasaki/vertex_normal_map.h, within float precision: every
// preset, random frames, views and SG axes (grazing and below the horizon among them), texels
// tilting up to ~40°, and SG widths from a broad sky lobe to a sun. Views within float round-off
// of either frame's horizon, where the model steps to zero, are not parity cases; nor are lobes
// with under 1e−3 of themselves above either horizon, whose share in float is erf's cancelling
// tail (their parts are as small, the ratio capped).
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "core/cloth_bsdf.h"
#include "core/normal_map_frame.h"
#include "gl/gl_program.h"
#include "gpu/egl_context.h"
#include "methods/fabric_uniforms.h"
#include "methods/iwasaki/vertex_normal_map.h"
#include "methods/program_cloth.h"
#include "methods/weave/weave_ratio.h"
#include "shaders/embedded_shaders.h"
#include "support/gpu_parity.h"
#include "support/random_direction.h"
#include "support/strict_glsl.h"

using namespace weft;
using namespace weft::gpu;
using glm::dvec3;

namespace {
// u_t: the texel (rgb) and the normal scale (a); u_wi: the SG's axis (xyz) and λ (w); u_l: the
// lobes' widening (x). Writes the ratio (u_mode 0: the model's, 1: the clamped cosine's) and
// whether the texel tilts.
const char* kFs = R"(
uniform highp sampler2D u_wo, u_n, u_u, u_wi, u_t, u_l;
uniform int u_mode;
out vec4 colour;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 wo = texelFetch(u_wo, p, 0).xyz, n = texelFetch(u_n, p, 0).xyz, u = texelFetch(u_u, p, 0).xyz;
  vec4 wi = texelFetch(u_wi, p, 0), texel = texelFetch(u_t, p, 0);
  vec3 t = tangent_space_normal(texel.rgb, texel.a);
  vec3 nb = n, ub = u;
  normal_mapped_frame(nb, ub, t);
  float widen2 = texelFetch(u_l, p, 0).x;
  vec3 r = u_mode == 0 ? normal_map_lobe_ratio(n, u, nb, ub, wi.xyz, wo, wi.w, widen2) : normal_map_cosine_ratio(n, nb, wi.xyz, wi.w);
  colour = vec4(r, normal_map_tilts(t) ? 1.0 : 0.0);
})";

std::string ratio_defines() {
  char d[200];
  std::snprintf(d, sizeof d,
                "#define NORMAL_MAP_RATIO_BIAS %.9e\n#define NORMAL_MAP_RATIO_CAP %.9e\n"
                "#define NORMAL_MAP_FLAT_TILT %.9e\n",
                kNormalMapRatioBias, kNormalMapRatioCap, kNormalMapFlatTilt);
  return d;
}
}  // namespace

class VertexNormalMapParity : public ::testing::TestWithParam<std::string> {};

TEST_P(VertexNormalMapParity, GlslMatchesTheCppTwin) {
  EglContext ctx = EglContext::headless();
  const Fabric fabric = load_fabric_preset(GetParam(), WEFT_SOURCE_ASSETS "/fabrics");
  const ClothBsdf bsdf = normal_map_ratio_bsdf(ClothBsdf(fabric, 16));
  // vertex_normal_map.glsl reads cloth_normal_map.glsl's uniforms only through normal_map_at,
  // which this test does not call; the parts are linked as the per-vertex draw links them.
  GlProgram program(fullscreen_triangle_vs(),
                    program_source({"microcylinder.glsl", "erf.glsl", "sg_lighting.glsl", "facet_horizon.glsl",
                                    "normal_map_frame.glsl", "cloth_normal_map.glsl", "vertex_normal_map.glsl"},
                                   ratio_defines()) +
                        kFs);
  program.use();
  upload_fabric(program, bsdf);

  constexpr int kW = 32, kH = 16, kCases = kW * kH;
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto unit = [&] { return test::random_unit(rng); };
  const double sharpness[] = {0.3, 6.0, 40.0, 400.0};
  std::vector<float> wo(4 * kCases), n(4 * kCases), uu(4 * kCases), wi(4 * kCases), tex(4 * kCases), widen(4 * kCases);
  for (int i = 0; i < kCases; ++i) {
    const dvec3 nn = unit();
    auto above = [&](dvec3 w) {  // mostly above the surface, some grazing
      if (glm::dot(w, nn) < 0.05) w = glm::normalize(w + (0.05 - glm::dot(w, nn) + u01(rng)) * nn);
      return w;
    };
    const SurfaceFrame f = SurfaceFrame::from_normal_warp(nn, unit());
    test::store_direction(wo, i, glm::vec3(above(unit())));
    test::store_direction(n, i, glm::vec3(f.n));
    test::store_direction(uu, i, glm::vec3(f.u));
    // SG axes anywhere, a third of them near the horizon.
    dvec3 axis = unit();
    if (i % 3 == 0) axis = glm::normalize(axis - (glm::dot(axis, nn) - 0.1 * (2 * u01(rng) - 1)) * nn);
    test::store_direction(wi, i, glm::vec3(axis));
    wi[4 * i + 3] = float(sharpness[i % 4]);
    widen[4 * i] = float(weave_lobe_widening(wi[4 * i + 3]));
    // Texels around flat, tilting up to ~40°; every 16th exactly an 8-bit flat code.
    const bool flat = i % 16 == 0;
    tex[4 * i] = float(flat ? 128.0 / 255.0 : 0.5 + 0.35 * (2 * u01(rng) - 1));
    tex[4 * i + 1] = float(flat ? 127.0 / 255.0 : 0.5 + 0.35 * (2 * u01(rng) - 1));
    tex[4 * i + 2] = float(0.8 + 0.2 * u01(rng));
    tex[4 * i + 3] = float(0.5 + u01(rng));
  }
  const std::vector<test::CaseInput> inputs = {{"u_wo", &wo}, {"u_n", &n}, {"u_u", &uu}, {"u_wi", &wi}, {"u_t", &tex}, {"u_l", &widen}};
  glUniform1i(program.uniform("u_mode"), 0);
  const std::vector<float> px = test::shade_cases(program, kW, kH, inputs);
  program.use();
  glUniform1i(program.uniform("u_mode"), 1);
  const std::vector<float> cosine = test::shade_cases(program, kW, kH, inputs);
  int compared = 0, flat_cases = 0, moved = 0;
  double worst = 0.0;
  for (int i = 0; i < kCases; ++i) {
    SurfaceFrame f;
    f.n = test::load_direction(n, i);
    f.u = test::load_direction(uu, i);
    f.v = glm::cross(f.n, f.u);
    const dvec3 o = test::load_direction(wo, i), l = test::load_direction(wi, i);
    const dvec3 t = tangent_space_normal(dvec3(tex[4 * i], tex[4 * i + 1], tex[4 * i + 2]), tex[4 * i + 3]);
    EXPECT_EQ(px[4 * i + 3] > 0.5f, normal_map_tilts(t)) << "case " << i;
    if (!normal_map_tilts(t)) {
      ++flat_cases;
      continue;
    }
    const SurfaceFrame b = normal_mapped_frame(f, t);
    const double margin = 2e-3;
    if (std::min(std::abs(glm::dot(f.n, o)), std::abs(glm::dot(b.n, o))) < margin) continue;
    const double lambda = wi[4 * i + 3];
    if (std::min(sg_hemisphere_fraction(lambda, glm::dot(l, f.n)), sg_hemisphere_fraction(lambda, glm::dot(l, b.n))) < 1e-3)
      continue;  // erf's tail: E's float value is round-off there
    const dvec3 expect = normal_map_lobe_ratio(bsdf, f, b, SphericalGaussian{l, lambda, dvec3(1.0)}, o);
    const dvec3 expect_cosine = normal_map_cosine_ratio(f.n, b.n, SphericalGaussian{l, lambda, dvec3(1.0)});
    for (int c = 0; c < 3; ++c) {
      const double ec = std::abs(cosine[4 * i + c] - expect_cosine[c]) / (1.0 + expect_cosine[c]);
      worst = std::max(worst, ec);
      EXPECT_LT(ec, 1e-3) << "cosine case " << i << ": GLSL " << cosine[4 * i + c] << ", C++ " << expect_cosine[c];
      const double e = std::abs(px[4 * i + c] - expect[c]) / (1.0 + expect[c]);
      worst = std::max(worst, e);
      EXPECT_LT(e, 1e-3) << "case " << i << " part " << c << ": GLSL " << px[4 * i + c] << ", C++ " << expect[c];
    }
    ++compared;
    moved += std::abs(expect.x - 1.0) > 0.05;
  }
  std::printf("%s: %d cases compared (%d flat), worst |glsl − c++|/(1 + r) %.2e\n", GetParam().c_str(), compared,
              flat_cases, worst);
  EXPECT_GT(compared, kCases * 2 / 3);
  EXPECT_EQ(flat_cases, kCases / 16);  // the 8-bit flat codes, and only they, read flat
  EXPECT_GT(moved, compared / 4);      // the tilts change the shading: the ratio's path is tested
}

INSTANTIATE_TEST_SUITE_P(Presets, VertexNormalMapParity,
                         ::testing::Values("linen_plain", "silk_crepe_de_chine", "polyester_satin_charmeuse",
                                           "polyester_satin_charmeuse_back", "silk_shot", "velvet"),
                         [](const auto& info) { return info.param; });
