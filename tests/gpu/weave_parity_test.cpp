// The weave layer: its GLSL (weave_layout.glsl, weave_ratio.glsl) against the C++ twin
// (methods/weave/weave_ratio.h, core/weave_layout.h, core/weave_coverage.h) case by case; and the
// whole layer drawn by the scene renderer over a swatch, averaged over whole repeats, against the
// same method without it (the layer adds detail, not light), per preset within 2 %.
#include <gtest/gtest.h>

#include <iostream>
#include <memory>
#include <random>

#include "core/cloth_bsdf.h"
#include "core/weave_coverage.h"
#include "core/weave_layout.h"
#include "frame/frame_render.h"
#include "gpu/egl_context.h"
#include "gl/gl_program.h"
#include "methods/fabric_uniforms.h"
#include "methods/program_cloth.h"
#include "methods/sg_lights.h"
#include "methods/weave/weave_float_table.h"
#include "methods/weave/weave_layer.h"
#include "methods/weave/weave_ratio.h"
#include "scene/scene_file.h"
#include "shaders/embedded_shaders.h"
#include "support/block_means.h"
#include "support/gpu_parity.h"
#include "support/random_direction.h"
#include "support/strict_glsl.h"

using namespace weft;
using namespace weft::gpu;
using glm::dvec3;

namespace {
const std::filesystem::path kAssets = WEFT_SOURCE_ASSETS;

SgLighting four_sgs() {
  return {SphericalGaussian{glm::normalize(dvec3(-0.45, -0.55, 0.70)), 40.0, {9.0, 8.6, 8.0}},
          SphericalGaussian{glm::normalize(dvec3(0.70, -0.35, 0.62)), 12.0, {1.6, 1.7, 1.9}},
          SphericalGaussian{dvec3(0, 0, 1), 2.0, {0.55, 0.6, 0.7}},
          SphericalGaussian{glm::normalize(dvec3(0.1, 0.9, 0.2)), 6.0, {0.8, 0.5, 0.3}}};
}

// Per pixel: ω_o, the frame, the tile point (u_st.xy), the fabric-level term, the four Qs and the
// four visibilities V_k; writes the factor (mode 0), the four Qs weave_terms gives (mode 1), its
// fabric-level term (mode 3), the factor filtered over the footprint whose tile-space
// derivatives are u_d's xy and zw (mode 2), or the same from the per-float table made at the
// pixel (mode 4: weave_table_node, weave_ratio_tabled), or the four Qs weave_q_group gives (mode 5)
// or weave_qs (mode 6: the layer's Qs over a per-vertex method's level).
const char* kFs = R"(
uniform highp sampler2D u_wo, u_n, u_u, u_st, u_fabric, u_q, u_d, u_vis;
uniform int u_mode;
out vec4 colour;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 wo = texelFetch(u_wo, p, 0).xyz, n = texelFetch(u_n, p, 0).xyz, u = texelFetch(u_u, p, 0).xyz;
  vec4 q[1], vis[1], weight[1];
  q[0] = texelFetch(u_q, p, 0);
  vis[0] = texelFetch(u_vis, p, 0);
  weave_weights(vis, q, weight);
  if (u_mode == 0) {
    colour = vec4(weave_ratio(n, u, wo, texelFetch(u_st, p, 0).xy, texelFetch(u_fabric, p, 0).xyz, weight), 1.0);
    return;
  }
  if (u_mode == 2) {
    highp vec4 d = texelFetch(u_d, p, 0);
    colour = vec4(weave_ratio_filtered(n, u, wo, texelFetch(u_st, p, 0).xy, d.xy, d.zw, texelFetch(u_fabric, p, 0).xyz, weight), 1.0);
    return;
  }
  if (u_mode == 4) {
    vec3 table[WEAVE_TABLE_NODES];
    for (int k = 0; k < WEAVE_TABLE_NODES; ++k) table[k] = weave_table_node(n, u, wo, k / WEAVE_TABLE_ARCS, k % WEAVE_TABLE_ARCS, weight);
    highp vec4 d = texelFetch(u_d, p, 0);
    colour = vec4(weave_ratio_tabled(texelFetch(u_st, p, 0).xy, d.xy, d.zw, texelFetch(u_fabric, p, 0).xyz, table), 1.0);
    return;
  }
  if (u_mode == 6) {
    vec4 alone[1];
    weave_qs(n, u, wo, alone);
    colour = alone[0];
    return;
  }
  vec3 fabric;
  vec4 terms_q[1];
  weave_terms(n, u, wo, vis, fabric, terms_q);
  colour = u_mode == 1 ? terms_q[0] : u_mode == 5 ? weave_q_group(n, u, wo, 0) : vec4(fabric, 1.0);
})";
}  // namespace

class WeaveParity : public ::testing::TestWithParam<std::string> {};

TEST_P(WeaveParity, GlslMatchesTheCppTwin) {
  EglContext ctx = EglContext::headless();
  const Fabric fabric = load_fabric_preset(GetParam(), kAssets / "fabrics");
  const ClothBsdf bsdf(fabric, kWeavePixelSamples);
  const WeaveLayout layout(fabric);
  const SgLighting sgs = four_sgs();
  // The program with `defines` after the layer's, its uniforms set (left in use).
  auto make_program = [&](const std::string& defines) {
    auto program = std::make_unique<GlProgram>(
        fullscreen_triangle_vs(),
        program_source({"microcylinder.glsl", "erf.glsl", "weave_layout.glsl", "weave_ratio.glsl", "weave_float_table.glsl"},
                       weave_defines(1) + defines) +
            kFs);
    program->use();
    upload_fabric(*program, bsdf);
    upload_weave_tilt_spreads(*program, bsdf);
    upload_weave_layout(*program, layout, fabric);
    std::vector<float> axes, powers, widen2;
    for (const auto& g : sgs) {
      const dvec3 p = sg_power(g);
      widen2.push_back(float(weave_lobe_widening(g.sharpness)));
      axes.insert(axes.end(), {float(g.axis.x), float(g.axis.y), float(g.axis.z)});
      powers.insert(powers.end(), {float(p.r), float(p.g), float(p.b)});
    }
    glUniform1i(program->uniform("u_sg_count"), 4);
    glUniform3fv(program->uniform("u_sg_axis"), 4, axes.data());
    glUniform3fv(program->uniform("u_sg_power"), 4, powers.data());
    glUniform1fv(program->uniform("u_sg_widen2"), 4, widen2.data());
    return program;
  };
  const std::unique_ptr<GlProgram> made = make_program("");
  const GlProgram& program = *made;

  constexpr int kW = 32, kH = 16, kCases = kW * kH;
  std::mt19937 rng(11), vis_rng(23);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto unit = [&] { return test::random_unit(rng); };
  std::vector<float> wo(4 * kCases), n(4 * kCases), uu(4 * kCases), st(4 * kCases), fab(4 * kCases), q(4 * kCases),
      d(4 * kCases), vis(4 * kCases);
  std::vector<std::vector<double>> visibility(kCases, std::vector<double>(4));
  std::vector<SurfaceFrame> frames(kCases);
  std::vector<dvec3> wos(kCases);
  std::vector<glm::dvec2> sts(kCases), dxs(kCases), dys(kCases);
  std::vector<WeaveTerms> terms(kCases);
  for (int i = 0; i < kCases; ++i) {
    const dvec3 nn = unit();
    dvec3 w = unit();
    if (glm::dot(w, nn) < 0.05) w = glm::normalize(w + (0.05 - glm::dot(w, nn) + u01(rng)) * nn);
    const SurfaceFrame f = SurfaceFrame::from_normal_warp(nn, unit());
    test::store_direction(wo, i, glm::vec3(w));
    test::store_direction(n, i, glm::vec3(f.n));
    test::store_direction(uu, i, glm::vec3(f.u));
    frames[i] = SurfaceFrame::from_normal_warp(test::load_direction(n, i), test::load_direction(uu, i));
    wos[i] = test::load_direction(wo, i);
    sts[i] = {float(3.0 * u01(rng)), float(3.0 * u01(rng))};
    st[4 * i] = float(sts[i].x), st[4 * i + 1] = float(sts[i].y);
    // Footprints from a twentieth of a repeat to a whole one, any orientation.
    for (int c = 0; c < 4; ++c) d[4 * i + c] = float((0.05 + 0.45 * u01(rng)) * (2.0 * u01(rng) - 1.0));
    dxs[i] = {d[4 * i], d[4 * i + 1]}, dys[i] = {d[4 * i + 2], d[4 * i + 3]};
    // Each light open, blocked or partly open (a quarter, a quarter, a half).
    for (int k = 0; k < 4; ++k) {
      const double r = u01(vis_rng);
      vis[4 * i + k] = float(r < 0.25 ? 1.0 : r < 0.5 ? 0.0 : u01(vis_rng));
      visibility[i][k] = vis[4 * i + k];
    }
    terms[i] = weave_terms(bsdf, frames[i], wos[i], sgs, visibility[i]);
    for (int c = 0; c < 3; ++c) fab[4 * i + c] = float(terms[i].fabric[c]);
    for (int k = 0; k < 4; ++k) q[4 * i + k] = float(terms[i].q[k]);
    // The twin's terms as the shader reads them (floats): its weights V_k/Q_k from the rounded Qs.
    terms[i].fabric = dvec3(fab[4 * i], fab[4 * i + 1], fab[4 * i + 2]);
    for (int k = 0; k < 4; ++k)
      if (terms[i].weight[k] > 0.0) terms[i].weight[k] = vis[4 * i + k] / double(q[4 * i + k]);
  }
  const std::vector<test::CaseInput> inputs = {{"u_wo", &wo}, {"u_n", &n}, {"u_u", &uu}, {"u_st", &st}, {"u_fabric", &fab}, {"u_q", &q}, {"u_d", &d}, {"u_vis", &vis}};
  glUniform1i(program.uniform("u_mode"), 0);
  const std::vector<float> ratio = test::shade_cases(program, kW, kH, inputs);
  program.use();
  glUniform1i(program.uniform("u_mode"), 1);
  const std::vector<float> qs = test::shade_cases(program, kW, kH, inputs);
  program.use();
  glUniform1i(program.uniform("u_mode"), 2);
  const std::vector<float> filtered = test::shade_cases(program, kW, kH, inputs);
  program.use();
  glUniform1i(program.uniform("u_mode"), 3);
  const std::vector<float> fabrics = test::shade_cases(program, kW, kH, inputs);
  program.use();
  glUniform1i(program.uniform("u_mode"), 5);
  const std::vector<float> group_qs = test::shade_cases(program, kW, kH, inputs);
  program.use();
  glUniform1i(program.uniform("u_mode"), 4);
  const std::vector<float> tabled = test::shade_cases(program, kW, kH, inputs);
  program.use();
  glUniform1i(program.uniform("u_mode"), 6);
  const std::vector<float> sweep_qs = test::shade_cases(program, kW, kH, inputs);
  int compared = 0, threads = 0, filtered_compared = 0, mixed = 0;
  for (int i = 0; i < kCases; ++i) {
    const WeaveTerms twin = weave_terms(bsdf, frames[i], wos[i], sgs, visibility[i]);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(qs[4 * i + k], twin.q[k], 2e-3 * (1.0 + twin.q[k])) << "case " << i << " SG " << k;
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(group_qs[4 * i + k], twin.q[k], 2e-3 * (1.0 + twin.q[k])) << "case " << i << " SG " << k << ", its group alone";
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(sweep_qs[4 * i + k], twin.q[k], 2e-3 * (1.0 + twin.q[k])) << "case " << i << " SG " << k << ", the Qs alone";
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(fabrics[4 * i + c], twin.fabric[c], 3e-3 * (1.0 + twin.fabric[c])) << "case " << i << " channel " << c;
    // A point within float round-off of a yarn's edge may fall either side: not a parity case.
    const WeaveSample here = layout.at(sts[i].x, sts[i].y);
    bool edge = false;
    for (double dx : {-1e-4, 1e-4})
      for (double dy : {-1e-4, 1e-4}) edge = edge || layout.at(sts[i].x + dx, sts[i].y + dy).thread != here.thread;
    // A pixel lit only by a lobe's tail far below its horizon (every other light blocked) has a
    // fabric-level term near RATIO_FLOOR: both sides' factors are then float noise over a black pixel.
    if (std::max({terms[i].fabric.r, terms[i].fabric.g, terms[i].fabric.b}) < 100.0 * kWeaveRatioFloor) continue;
    // The filtered factor is continuous in st except where a thread's largest piece changes
    // (its arc jumps): a case whose twin moves there under a nudge of float round-off is skipped.
    const dvec3 expect_filtered = weave_ratio_filtered(bsdf, layout, frames[i], wos[i], sts[i], dxs[i], dys[i], terms[i], sgs);
    bool jump = false;
    for (double dx : {-1e-4, 1e-4})
      for (double dy : {-1e-4, 1e-4}) {
        const dvec3 nudged = weave_ratio_filtered(bsdf, layout, frames[i], wos[i], sts[i] + glm::dvec2(dx, dy), dxs[i], dys[i], terms[i], sgs);
        for (int c = 0; c < 3; ++c) jump = jump || std::abs(nudged[c] - expect_filtered[c]) > 1e-3 * (1.0 + expect_filtered[c]);
      }
    if (!jump) {
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(filtered[4 * i + c], expect_filtered[c], 3e-3 * (1.0 + expect_filtered[c])) << "filtered case " << i << " channel " << c;
      const dvec3 expect_tabled = weave_ratio_tabled(layout, weave_float_table(bsdf, frames[i], wos[i], terms[i], sgs), sts[i],
                                                     dxs[i], dys[i], terms[i].fabric);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(tabled[4 * i + c], expect_tabled[c], 3e-3 * (1.0 + expect_tabled[c]))
            << "filtered case " << i << " channel " << c << ", from the table";
      ++filtered_compared;
      const WeaveCoverage cover = weave_coverage(layout, sts[i], dxs[i], dys[i]);
      mixed += cover.share[0] > 0.0 && cover.share[1] > 0.0;
    }
    if (edge) continue;
    const dvec3 expect = weave_ratio(bsdf, layout, frames[i], wos[i], sts[i], terms[i], sgs);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(ratio[4 * i + c], expect[c], 3e-3 * (1.0 + expect[c])) << "case " << i << " channel " << c;
    ++compared;
    threads += here.thread >= 0;
  }
  EXPECT_GT(compared, kCases * 9 / 10);
  // The velvet's weft jumps −55° → 55° along its float: wherever one of a float's three arcs lies on
  // the jump, a nudge moves its tilt across it.
  EXPECT_GT(filtered_compared, kCases * 3 / 4);
  EXPECT_GT(mixed, filtered_compared / 4);  // footprints that straddle an edge are tested too
  EXPECT_GT(threads, compared / 3);
}

INSTANTIATE_TEST_SUITE_P(Presets, WeaveParity,
                         ::testing::Values("linen_plain", "polyester_satin_charmeuse", "silk_crepe_de_chine", "velvet"));

// The scene renderer with and without the layer over a swatch seen square from above, 80 px per
// repeat: block means over whole repeats agree, and single pixels do not. The swatch's 3 cm
// triangles span 50 px here, as a furniture mesh's do in a close-up; the method's shading is
// interpolated across them, the layer's fabric-level term is the pixel's own.
TEST(WeaveLayer, AveragedOverRepeatsEqualsTheMethodWithoutIt) {
  constexpr int kSize = 160, kBlock = 80;
  for (const std::string& name : list_fabric_presets(kAssets / "fabrics")) {
    const std::string json = R"({"name": "top", "environment": "studio",
      "camera": {"position": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": )" +
                             std::to_string(2.0 * std::atan(0.05) * 180.0 / M_PI) + R"(},
      "objects": [{"name": "swatch", "material": "cloth", "fabric": ")" + name + R"(",
                   "weave_repeats_per_uv": [20, 20], "mesh": {"generator": "swatch", "size": 1.0, "resolution": 32}}]})";
    const Scene scene = parse_scene(json, "top.json", kAssets / "scenes");
    const std::map<std::string, Fabric> fabrics{{name, load_fabric_preset(name, kAssets / "fabrics")}};
    const GpuFrame plain = render_gpu_frame(scene, fabrics, four_sgs(), "sgpoint", kSize, kSize, 0);
    const GpuFrame woven = render_gpu_frame(scene, fabrics, four_sgs(), "sgpoint", kSize, kSize, 0, nullptr,
                                            Backdrop::measure, /*weave=*/true);
    const test::BlockComparison c = test::compare_blocks(plain.image, woven.image, kBlock);
    std::cout << name << ": layer averaged over repeats against the method alone " << c.block_means << "\n";
    EXPECT_LT(c.block_means, 0.02) << name;
    EXPECT_GT(c.pixels, 0.3) << name;
  }
}

// UVs collapsed to one point leave the threads no place: the layer leaves the method's shading as
// it is there, pixel for pixel; the same swatch with its UVs draws the weave (the control).
TEST(WeaveLayer, CollapsedUvsLeaveTheMethodsShading) {
  constexpr int kSize = 96;
  const std::string name = "linen_plain";
  const std::string json = R"({"name": "top", "environment": "studio",
    "camera": {"position": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": )" +
                           std::to_string(2.0 * std::atan(0.05) * 180.0 / M_PI) + R"(},
    "objects": [{"name": "swatch", "material": "cloth", "fabric": ")" + name + R"(",
                 "weave_repeats_per_uv": [20, 20], "mesh": {"generator": "swatch", "size": 1.0, "resolution": 8}}]})";
  Scene scene = parse_scene(json, "top.json", kAssets / "scenes");
  const std::map<std::string, Fabric> fabrics{{name, load_fabric_preset(name, kAssets / "fabrics")}};
  auto differing = [&](const Scene& s) {
    const GpuFrame plain = render_gpu_frame(s, fabrics, four_sgs(), "sgpoint", kSize, kSize, 0);
    const GpuFrame woven = render_gpu_frame(s, fabrics, four_sgs(), "sgpoint", kSize, kSize, 0, nullptr, Backdrop::measure, true);
    size_t n = 0;
    for (size_t i = 0; i < plain.image.pixels.size(); ++i) n += plain.image.pixels[i] != woven.image.pixels[i];
    return n;
  };
  EXPECT_GT(differing(scene), size_t(kSize * kSize / 4)) << "the layer did not draw the swatch with its UVs";
  for (auto& uv : scene.objects[0].mesh.uvs) uv = glm::dvec2(0.37, 0.61);
  EXPECT_EQ(differing(scene), 0u) << "pixels the layer changed where the UVs collapse";
}
