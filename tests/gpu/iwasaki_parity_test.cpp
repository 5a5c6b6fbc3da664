// Parity: methods/iwasaki/iwasaki.glsl, drawn by SceneRenderer (method iwasaki per pixel, and
// iwasaki_vertex per vertex, interpolated) on the GL driver
// (llvmpipe here) and read back, agrees with the C++ evaluation of the same approximation
// (methods/iwasaki/iwasaki.cpp with iwasaki_visibility.cpp's SDF lookup and the baked κ) within 1e−3
// relative at sample pixels. Both consume the same baked data: the weighting tables, the
// per-(vertex, SG) SDF values reconstructed from the PCA when the lighting is set, and κ. The C++ side finds each pixel's surface
// point by casting the pixel's camera ray (Embree), which gives the same perspective-correct
// barycentrics the rasteriser interpolates with. For iwasaki_vertex the C++ side evaluates the
// triangle's three vertices (each with its own SDF grid) and blends them with those barycentrics;
// iwasaki_vertex_mask the same with each vertex's V_k from its visibility mask in place of the SDF;
// iwasaki_mask per pixel, the three vertices' V_k blended with the barycentrics.
// iwasaki_vertex_quadrature and iwasaki_quadrature: the broad SGs (λ < λ_b) by the quadrature of
// broad_lobe_quadrature.cpp at the triangle's vertices, with each cell's bit from the vertex's
// mask, blended with the barycentrics; iwasaki (SDF) over the others, per vertex or per pixel;
// iwasaki_mask_quadrature and iwasaki_vertex_mask_quadrature the same with the masks' V_k over the others.
// Each SG is also cut by the triangle's own plane (facet_horizon_factor: the GPU takes the facet
// normal from the position's screen derivatives, the C++ side from the triangle): per pixel inside
// iwasaki, per vertex after blending each SG's radiance at the three vertices
// (facet_interpolated_radiance), at the interpolated shading normal.
// Textured cases put a smooth map on each thread (a different one on the warp and the weft): per
// pixel the C++ side tints each thread's volume part by its texel at the pixel's UV; per vertex
// it keeps each SG's terms at the vertices and tints them at the pixel, as the GPU's split does.
// A colour knob on a textured cloth (set_fabric, no pass recomputed) draws what a renderer made
// with that colour draws. A bumped case adds a smooth normal map on the per-vertex rungs: the C++
// side multiplies each SG's parts by normal_map_ratios at the pixel's frame and texel.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <memory>
#include <span>
#include <vector>

#include "bake/visibility/scene_visibility.h"
#include "bake/visibility/sigmoid_gain.h"
#include "bake/visibility/visibility_mask_bake.h"
#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"
#include "gpu/egl_context.h"
#include "gl/offscreen_target.h"
#include "gpu/scene_renderer.h"
#include "methods/iwasaki/broad_lobe_quadrature.h"
#include "methods/iwasaki/iwasaki.h"
#include "methods/iwasaki/iwasaki_visibility.h"
#include "methods/iwasaki/vertex_normal_map.h"
#include "methods/registry.h"
#include "reference/ray_scene.h"
#include "scene/scene_file.h"
#include "support/gpu_parity.h"
#include "support/parity_bake_settings.h"
#include "support/ray_pixels.h"
#include "support/strict_glsl.h"

using namespace weft;

namespace {

SgLighting test_lights() {
  // A few lobes of different sharpness, one from low on the side so the floor shadows the pillow.
  SgLighting l;
  l.push_back({glm::normalize(dvec3(0.3, -0.5, 0.8)), 40.0, dvec3(3.0, 2.5, 2.0)});
  l.push_back({glm::normalize(dvec3(-0.9, 0.1, 0.15)), 12.0, dvec3(0.8, 1.0, 1.3)});
  l.push_back({glm::normalize(dvec3(0.2, 0.9, 0.4)), 3.0, dvec3(0.4, 0.4, 0.5)});
  l.push_back({glm::normalize(dvec3(0.0, 0.0, 1.0)), 150.0, dvec3(2.0, 2.0, 2.0)});
  // A sky's broad ground lobe, below every surface facing up: shaded as its part above the
  // surface (above_horizon), at a λ' between T's levels.
  l.push_back({glm::normalize(dvec3(0.1, 0.2, -0.97)), 0.3, dvec3(0.5, 0.6, 0.4)});
  // A low sun as a sky's fit gives it (one lobe at the fit's cap, λ = 1000) and its ring (λ ≈ 19):
  // satin's narrow lobes read T at their peak for these (iwasaki.cpp: at fiber_direction of the peak).
  l.push_back({glm::normalize(dvec3(-0.4, -0.8, 0.15)), 1000.0, dvec3(30.0, 28.0, 25.0)});
  l.push_back({glm::normalize(dvec3(-0.4, -0.8, 0.2)), 19.0, dvec3(1.5, 1.4, 1.2)});
  // A sun 2° below the swatch's horizon: only its sliver lights the cloth (above_horizon's sharp rule).
  l.push_back({glm::normalize(dvec3(0.9, -0.4, -0.034)), 500.0, dvec3(6.0, 5.0, 4.0)});
  return l;
}

struct Case {
  std::string scene, fabric;
  bool expect_visibility;
  bool textured = false;
  bool bumped = false;  // a normal map too (per-vertex rungs)
  // The camera mirrored below the cloth's plane (z = 0), the floor taken away: every pixel sees the
  // cloth's back side,
  // which the bake cast nothing for, so its visibility must change nothing.
  bool from_behind = false;
};

// A smooth, periodic map, one per thread, read at a small scale (a sixteenth of a period across
// the pillow): even a grazing pixel's footprint (the GPU's mip level) then blurs it by under 1e−4,
// so the GPU's trilinear lookup and the C++ side's bilinear one agree (the accuracy test checks a
// sharp checker against the reference, whose supersampled pixels average the footprint).
std::shared_ptr<const TextureImage> smooth_map(int phase) {
  // 128 texels a period: neighbours differ by a few 8-bit steps, so the GPU's filter weights (8
  // bits on llvmpipe) cost under 1e−4 of a texel.
  constexpr int n = 128;
  auto t = std::make_shared<TextureImage>();
  t->width = t->height = n;
  t->rgba.resize(n * n * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double a = 2 * 3.14159265358979 * x / n, b = 2 * 3.14159265358979 * y / n;
      uint8_t* p = &t->rgba[(size_t(y) * n + x) * 4];
      p[0] = uint8_t(std::lround(150 + 100 * std::sin(a + phase)));
      p[1] = uint8_t(std::lround(150 + 100 * std::cos(b)));
      p[2] = uint8_t(std::lround(150 + 100 * std::sin(a + b + phase)));
      p[3] = 255;
    }
  return t;
}

// Smooth bumps tilting up to ~17° along and across, 128 texels a period (as smooth_map, for the
// GPU's filtered lookup to agree with the C++ side's bilinear one).
std::shared_ptr<const TextureImage> smooth_bumps() {
  constexpr int n = 128;
  auto t = std::make_shared<TextureImage>();
  t->width = t->height = n;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double a = 2 * 3.14159265358979 * x / n, b = 2 * 3.14159265358979 * y / n;
      const glm::dvec3 d = glm::normalize(glm::dvec3(0.3 * std::sin(a), 0.2 * std::cos(b), 1.0));
      t->rgba.insert(t->rgba.end(), {uint8_t(std::lround(127.5 + 127.5 * d.x)), uint8_t(std::lround(127.5 + 127.5 * d.y)),
                                     uint8_t(std::lround(127.5 + 127.5 * d.z)), uint8_t(255)});
    }
  return t;
}

class IwasakiParity : public ::testing::TestWithParam<Case> {};

void check_parity(const Case& c, const methods::RuntimeMethod& method) {
  const bool per_vertex = method.name.starts_with("iwasaki_vertex");
  const bool masks = method.name.find("_mask") != std::string::npos;
  const bool quadrature = method.name.ends_with("quadrature");
  Scene scene = load_scene_preset(c.scene, WEFT_SOURCE_ASSETS "/scenes");
  if (c.from_behind) {  // below the cloth, without the floor that would hide it
    scene.camera.position.z = -scene.camera.position.z;
    std::erase_if(scene.objects, [](const SceneObject& o) { return o.name == "floor"; });
  }
  const Fabric fabric = load_fabric_preset(c.fabric, WEFT_SOURCE_ASSETS "/fabrics");
  size_t cloth_index = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].material == Material::cloth) {
      scene.objects[i].fabric = c.fabric;
      cloth_index = i;
      if (c.textured) {
        scene.objects[i].thread_maps[0] = ThreadMap{smooth_map(0), "warp", {{0.1, 0.2}, {0.06, 0.06}, 0.0}};
        scene.objects[i].thread_maps[1] = ThreadMap{smooth_map(2), "weft", {{0.4, 0.0}, {0.05, 0.07}, 0.6}};
      }
      if (c.bumped) scene.objects[i].normal_map = NormalMap{ThreadMap{smooth_bumps(), "bumps", {{0.3, 0.1}, {0.07, 0.05}, 0.3}}, 1.0};
    }
  auto data = std::make_shared<ShadingData>();
  data->tables.emplace(c.fabric, bake_weighting_tables(fabric, test::parity_bake_settings()));
  SceneVisibilityOptions vo;
  vo.resolution = 16;
  if (auto v = bake_object_visibility(scene, cloth_index, vo)) data->visibility.emplace(cloth_index, std::move(*v));
  if (auto m = bake_visibility_mask(scene, cloth_index, 16)) data->masks.emplace(cloth_index, std::move(*m));
  ASSERT_EQ(data->visibility.size(), c.expect_visibility ? 1u : 0u);
  SigmoidGainTableSpec ks;
  ks.sigma_l_count = ks.sigma_prime_count = 5;
  ks.beta_count = 9;
  if (c.expect_visibility) data->kappa = fit_sigmoid_gain_table(ks);

  const int w = 80, h = 60;
  const SgLighting sgs = test_lights();
  gpu::EglContext ctx = gpu::EglContext::headless();
  gpu::SceneRenderer renderer(scene, {fabric}, method, 16, data);
  EXPECT_TRUE(renderer.warnings().empty()) << renderer.warnings().front();
  renderer.set_lighting(sgs);
  gpu::OffscreenTarget target(w, h);
  target.bind();
  renderer.draw(scene.camera, w, h);
  const Image gpu_image = gpu::read_linear_image(w, h);
  if (c.textured) {
    // A colour knob: the warp redder, the weft darker, drawn without recomputing the per-vertex
    // pass; a renderer made in that colour draws the same.
    Fabric recoloured = fabric;
    recoloured.threads[0].albedo *= dvec3(1.5, 0.6, 0.8);
    recoloured.threads[1].albedo *= 0.5;
    renderer.set_fabric(0, recoloured);
    renderer.draw(scene.camera, w, h);
    const Image knob = gpu::read_linear_image(w, h);
    gpu::SceneRenderer fresh(scene, {recoloured}, method, 16, data);
    fresh.set_lighting(sgs);
    fresh.draw(scene.camera, w, h);
    const Image made = gpu::read_linear_image(w, h);
    double worst_knob = 0, changed = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const double scale = std::max({made.at(x, y).r, made.at(x, y).g, made.at(x, y).b, 1e-3});
        worst_knob = std::max(worst_knob, glm::length(knob.at(x, y) - made.at(x, y)) / scale);
        changed = std::max(changed, glm::length(knob.at(x, y) - gpu_image.at(x, y)) / scale);
      }
    EXPECT_LT(worst_knob, 1e-4) << "a colour knob on a textured cloth draws otherwise than that colour";
    EXPECT_GT(changed, 0.05) << "the colour knob changed nothing";
    target.bind();
    renderer.set_fabric(0, fabric);
  }

  // The C++ side, from the same data.
  const WeightingTables& tables = data->tables.at(c.fabric);
  const ClothBsdf bsdf(fabric, tables.tangent_samples);
  const TriangleMesh& mesh = scene.objects[cloth_index].mesh;
  std::unique_ptr<SgVisibility> grids;
  if (c.expect_visibility)
    grids = std::make_unique<SgVisibility>(masks ? SgVisibility::from_mask(data->masks.at(cloth_index), mesh, sgs)
                                                 : SgVisibility::compute(data->visibility.at(cloth_index), mesh, sgs, true));
  // The broad lobes' cell bits (all open without a mask) and how many of them the mask closes.
  const std::vector<int> slots = broad_lobe_slots(sgs);
  const auto mask = data->masks.find(cloth_index);
  const BroadLobeBits bits = mask != data->masks.end() ? BroadLobeBits::compute(mask->second, mesh, sgs)
                                                       : BroadLobeBits::all_open(mesh.positions.size());
  const BroadLobeBits open_bits = BroadLobeBits::all_open(mesh.positions.size());
  if (quadrature) {
    ASSERT_GE(*std::max_element(slots.begin(), slots.end()), 1) << "the lighting should hold two broad lobes";
    size_t closed = 0;
    for (std::uint32_t w : bits.words) closed += size_t(std::popcount(~w));
    if (c.expect_visibility) { EXPECT_GT(closed, 0u) << "no broad cell is blocked: the mask path went untested"; }
  }
  // Textured: the GPU's filtered sRGB texels differ from the C++ side's exact bilinear ones by
  // about 1e−3 on llvmpipe (measured 0.9–1.3e−3 here, the same per pixel and per vertex, while the
  // untextured cases agree to 3e−6): the texture's precision, not the split's.
  // Bumped: the normal map's filtered texels move each sharp lobe's ratio too (measured up to
  // 4e−3 here with smooth bumps, 1.2e−3 with one constant tilt, whose texels filter exactly).
  const double tolerance = test::driver_tolerance(c.bumped ? 5e-3 : c.textured ? 2.5e-3 : 1e-3);
  const RayScene rays(scene);
  int compared = 0, occluded_pixels = 0;
  double broad_share = 0;
  long facet_cuts = 0;  // (pixel, SG) pairs the facet's plane cuts by more than 1 %
  double worst = 0, visibility_effect = 0, bump_effect = 0;
  bool use_ratios = true;
  for (int y = 1; y < h - 1; y += 2)
    for (int x = 1; x < w - 1; x += 2) {
      const dvec3 dir = camera_ray(scene.camera, w, h, x + 0.5, y + 0.5);
      const auto hit = rays.intersect(scene.camera.position, dir);
      if (!hit || hit->object != cloth_index) continue;
      // Away from triangle edges and silhouettes: the two sides may pick different triangles there.
      const double b0 = 1 - hit->b1 - hit->b2;
      if (std::min({b0, hit->b1, hit->b2}) < 0.02) continue;
      if (!test::interior_pixel(rays, scene.camera, w, h, x, y, cloth_index)) continue;
      const auto& tri = mesh.triangles[hit->triangle];
      const dvec3 bary(b0, hit->b1, hit->b2);
      // The radiance at surface point (bary over `corners`, SDF blended over `sdf_corners`).
      // The facet's plane, facing the eye at the pixel.
      const test::MeshPoint here = test::mesh_point(mesh, tri, bary);
      const dvec3 wo_here = glm::normalize(scene.camera.position - here.position);
      const dvec3 p0 = mesh.positions[tri[0]], p1 = mesh.positions[tri[1]], p2 = mesh.positions[tri[2]];
      dvec3 facet = glm::normalize(glm::cross(p1 - p0, p2 - p0));
      if (glm::dot(facet, wo_here) < 0) facet = -facet;
      dvec3 shading_normal = glm::normalize(here.normal);
      if (glm::dot(shading_normal, wo_here) < 0) shading_normal = -shading_normal;
      for (const auto& g : sgs)
        if (facet_horizon_factor(g, shading_normal, facet) < 0.99) ++facet_cuts;
      // SG `only` (−1: all of them).
      auto radiance = [&](dvec3 b, std::array<uint32_t, 3> sdf_corners, dvec3 sdf_bary, bool with_visibility, int only) {
        const test::MeshPoint m = test::mesh_point(mesh, tri, b);
        const dvec3 p = m.position, warp = m.warp;
        dvec3 n = m.normal;
        const dvec3 wo = glm::normalize(scene.camera.position - p);
        n = glm::normalize(n);
        const bool behind = glm::dot(n, wo) < 0;
        if (behind) n = -n;
        const SurfaceFrame frame = SurfaceFrame::from_normal_warp(n, warp);
        IwasakiVisibility vis;
        if (grids && masks) {
          vis.open_share = [&](int sg) {
            double share = 0;  // blended over the triangle's vertices as the SDF's values are
            for (int i = 0; i < 3; ++i)
              if (sdf_bary[i] != 0) share += sdf_bary[i] * grids->at(sdf_corners[i], sg).x;
            if (share < 0.9) ++occluded_pixels;
            return share;
          };
        } else if (grids) {
          vis.kappa = &*data->kappa;
          vis.sdf = [&](int sg, const ThreadFrame& tf, double theta, double phi, double& d, double& dt, double& dp) {
            const SdfSample s = sdf_in_sample_frame(*grids, sg, frame, sdf_corners, sdf_bary, tf, theta, phi);
            d = s.d;
            dt = s.d_dtheta;
            dp = s.d_dphi;
            if (d < 0.1) ++occluded_pixels;
          };
        }
        if (!(grids && with_visibility)) vis = IwasakiVisibility{};
        if (!per_vertex) vis.facet_normal = facet;  // per pixel: inside iwasaki (facet_horizon_factor)
        vis = on_side_shaded(vis, behind);
        const IwasakiVisibility* v = &vis;
        if (only >= 0) return iwasaki_sg_radiance(bsdf, tables, frame, wo, sgs, size_t(only), v);
        if (quadrature) return iwasaki_narrow_radiance(bsdf, tables, frame, wo, sgs, slots, v);
        return iwasaki_radiance(bsdf, tables, frame, wo, sgs, v);
      };
      // Each thread's texel at the pixel (1 untextured).
      const SceneObject& cloth_object = scene.objects[cloth_index];
      const std::array<dvec3, 2> tint = {thread_tint(cloth_object, 0, here.uv), thread_tint(cloth_object, 1, here.uv)};
      // The broad lobes' quadrature at vertex i of the triangle.
      auto broad = [&](int i, bool with_visibility, int only) {
        dvec3 one(0);
        one[i] = 1;
        const test::MeshPoint m = test::mesh_point(mesh, tri, one);
        const dvec3 wo = glm::normalize(scene.camera.position - m.position);
        dvec3 n = glm::normalize(m.normal);
        if (glm::dot(n, wo) < 0) n = -n;
        const BroadLobeBits& b = with_visibility ? bits : open_bits;
        std::vector<int> chosen = slots;  // SG `only`'s slot alone (−1: every broad SG)
        if (only >= 0)
          for (size_t k = 0; k < chosen.size(); ++k)
            if (int(k) != only) chosen[k] = -1;
        return broad_lobe_terms(bsdf, SurfaceFrame::from_normal_warp(n, m.warp), wo, sgs, chosen, b.vertex(tri[i]));
      };
      auto shade = [&](bool with_visibility) {
        if (!per_vertex) {
          dvec3 sum(0);
          if (quadrature)
            for (int k = 0; k < 3; ++k) sum += bary[k] * broad(k, with_visibility, -1).tinted(tint);
          return sum + radiance(bary, {tri[0], tri[1], tri[2]}, bary, with_visibility, -1).tinted(tint);
        }
        // Per vertex: each SG at each vertex (its quadrature where broad), then the facet's cut.
        std::array<std::vector<IwasakiTerms>, 3> at;
        for (int i = 0; i < 3; ++i) {
          dvec3 one(0);
          one[i] = 1;
          for (size_t k = 0; k < sgs.size(); ++k)
            at[i].push_back(quadrature && slots[k] >= 0
                                ? broad(i, with_visibility, int(k))
                                : radiance(one, {tri[i], tri[i], tri[i]}, dvec3(1, 0, 0), with_visibility, int(k)));
        }
        const std::span<const int> broad_slots = quadrature ? std::span<const int>(slots) : std::span<const int>();
        if (c.bumped && use_ratios)
          return normal_mapped_facet_radiance(normal_map_ratio_bsdf(bsdf), sgs, broad_slots, {at[0], at[1], at[2]}, bary,
                                              SurfaceFrame::from_normal_warp(shading_normal, here.warp), facet, tint,
                                              normal_map_tangent(cloth_object, here.uv), wo_here);
        return facet_interpolated_radiance(sgs, broad_slots, {at[0], at[1], at[2]}, bary, shading_normal, facet, tint);
      };
      const dvec3 cpu = shade(true);
      if (c.bumped) {  // how much the normal map changes this pixel: parity must cover it
        use_ratios = false;
        const dvec3 unmapped = shade(true);
        use_ratios = true;
        bump_effect = std::max(bump_effect, glm::length(unmapped - cpu) / glm::length(cpu));
      }
      if (quadrature) {
        dvec3 b(0);
        for (int k = 0; k < 3; ++k) b += bary[k] * broad(k, true, -1).tinted(tint);
        broad_share = std::max(broad_share, glm::length(b) / glm::length(cpu));
      }
      if (grids) {  // how much the visibility path changes this pixel: parity must cover it
        const dvec3 open = shade(false);
        visibility_effect = std::max(visibility_effect, glm::length(open - cpu) / glm::length(open));
      }
      const dvec3 g = gpu_image.at(x, y);
      const double scale = std::max({cpu.r, cpu.g, cpu.b});
      ASSERT_GT(scale, 0.0) << "pixel " << x << "," << y;
      for (int k = 0; k < 3; ++k) {
        const double e = std::abs(g[k] - cpu[k]) / scale;
        worst = std::max(worst, e);
        EXPECT_LT(e, tolerance) << "pixel " << x << "," << y << " channel " << k << ": GLSL " << g[k] << ", C++ " << cpu[k];
      }
      ++compared;
    }
  ::testing::Test::RecordProperty("worst_relative", std::to_string(worst));
  std::printf("%s %s/%s: %d pixels compared, worst relative difference %.2e; visibility changes a pixel by up to %.1f %%\n",
              method.name.c_str(), c.scene.c_str(), c.fabric.c_str(), compared, worst, 100 * visibility_effect);
  EXPECT_GT(compared, 40);
  if (c.expect_visibility) { EXPECT_GT(facet_cuts, 0) << "no SG cut by a facet: the facet path went untested"; }
  if (c.bumped) { EXPECT_GT(bump_effect, 0.05) << "the normal map hardly changes any compared pixel: its ratio went untested"; }
  if (quadrature) { EXPECT_GT(broad_share, 0.1) << "the broad lobes hardly light any compared pixel: the quadrature went untested"; }
  if (c.from_behind) {
    EXPECT_LT(visibility_effect, 1e-12) << "the baked side's visibility shaded the cloth's back side";
  } else if (c.expect_visibility) {
    EXPECT_GT(occluded_pixels, 0) << "no lookup near a shadow edge: the visibility path went untested";
    EXPECT_GT(visibility_effect, 0.05) << "visibility hardly changes any compared pixel: the path went untested";
  }
}

TEST_P(IwasakiParity, PerPixelGlslMatchesCpp) { check_parity(GetParam(), methods::method("iwasaki")); }
TEST_P(IwasakiParity, PerPixelMaskGlslMatchesCpp) { check_parity(GetParam(), methods::method("iwasaki_mask")); }
TEST_P(IwasakiParity, PerVertexGlslMatchesCpp) { check_parity(GetParam(), methods::method("iwasaki_vertex")); }
TEST_P(IwasakiParity, PerVertexMaskGlslMatchesCpp) { check_parity(GetParam(), methods::method("iwasaki_vertex_mask")); }
TEST_P(IwasakiParity, PerVertexQuadratureGlslMatchesCpp) {
  check_parity(GetParam(), methods::method("iwasaki_vertex_quadrature"));
}
TEST_P(IwasakiParity, PerPixelQuadratureGlslMatchesCpp) { check_parity(GetParam(), methods::method("iwasaki_quadrature")); }
TEST_P(IwasakiParity, PerVertexMaskQuadratureGlslMatchesCpp) {
  check_parity(GetParam(), methods::method("iwasaki_vertex_mask_quadrature"));
}
TEST_P(IwasakiParity, PerPixelMaskQuadratureGlslMatchesCpp) {
  check_parity(GetParam(), methods::method("iwasaki_mask_quadrature"));
}

// The per-vertex rungs' normal map on the textured pillow (with shadows): their GLSL ratio and
// the C++ twin at the pixel.
TEST(IwasakiParityNormalMap, PerVertexGlslMatchesCpp) {
  for (const char* method : {"iwasaki_vertex", "iwasaki_vertex_quadrature"})
    check_parity(Case{"pillow", "linen_plain", true, true, true}, methods::method(method));
}

INSTANTIATE_TEST_SUITE_P(Scenes, IwasakiParity,
                         ::testing::Values(Case{"swatch", "silk_shot", false}, Case{"pillow", "linen_plain", true},
                                           Case{"pillow", "polyester_satin_charmeuse", true},
                                           Case{"pillow", "linen_plain", true, true},
                                           Case{"drape", "linen_plain", true, false, false, true}),
                         [](const auto& info) {
                           return info.param.scene + "_" + info.param.fabric + (info.param.textured ? "_textured" : "") +
                                  (info.param.from_behind ? "_from_behind" : "");
                         });

}  // namespace
