// Error budget of iwasaki under skies (bench label, no assertions; docs/research/iwasaki.md, "Visibility or
// shading under a low sun"): per cloth pixel of a scene's camera, the C++ twin of iwasaki against
// the reference, with and without occlusion by the scene, split per SG. Variants:
//   open   iwasaki with no visibility (the surface's horizon only) vs the reference with shadow
//          rays off: the shading's error alone;
//   sdf    iwasaki with the bundle's SDF visibility (what the bench's GPU image shows) vs the
//          reference: the bench's error;
//   exact  iwasaki with each SG's amplitude times its exact lobe-averaged visibility
//          V_k = ∫G_k V dω / ∫G_k dω over the part of G_k above the surface (ray cast, 16×16
//          strata of G_k's own distribution), vs the reference: what exact visibility buys;
// and the same three per vertex (iwasaki_vertex: each corner shaded with its own SDF or V_k,
// blended with the pixel's barycentrics), and per vertex with V_k from the baked visibility mask
// (iwasaki_vertex_mask; $WEFT_STUDY_MASK cells per side, default 64). Writes budget.csv and per_sg.csv to
// $WEFT_STUDY_OUT (default: the working directory). Cases: pillow and drape in linen under
// sky:elev=5 and sky:elev=20, at $WEFT_STUDY_WIDTH×$WEFT_STUDY_HEIGHT (default 160×120); the
// bundle (paper settings, or $WEFT_STUDY_GRID / $WEFT_STUDY_SDF for a quick look) is cached in
// $WEFT_STUDY_CACHE (default: the working directory).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "bake/writers/shading_data_writer.h"
#include "bake/scene/scene_bake.h"
#include "bake/visibility/visibility_mask_bake.h"
#include "measure/image_metrics.h"
#include "core/fabric.h"
#include "lighting/env_spec.h"
#include "lighting/sg_fit.h"
#include "methods/iwasaki/iwasaki.h"
#include "methods/iwasaki/iwasaki_visibility.h"
#include "reference/ray_scene.h"
#include "reference/scene_render.h"
#include "reference/sg_quadrature.h"
#include "scene/scene_file.h"
#include "support/ray_pixels.h"
#include "support/scene_case.h"

using namespace weft;

namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : fallback;
}
std::filesystem::path env_path(const char* name) {
  const char* v = std::getenv(name);
  return v && *v ? std::filesystem::path(v) : std::filesystem::current_path();
}

// A direction of G's own distribution (density ∝ e^{λ(ω·ξ − 1)}) at strata coordinates (u, v).
dvec3 sg_direction(const SphericalGaussian& g, double u, double v) {
  const double c = std::clamp(1.0 + std::log(u + (1.0 - u) * std::exp(-2.0 * g.sharpness)) / g.sharpness, -1.0, 1.0);
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c)), phi = 2.0 * std::numbers::pi * v;
  const dvec3 a = std::abs(g.axis.z) < 0.9 ? dvec3(0, 0, 1) : dvec3(1, 0, 0);
  const dvec3 x = glm::normalize(glm::cross(a, g.axis)), y = glm::cross(g.axis, x);
  return c * g.axis + s * (std::cos(phi) * x + std::sin(phi) * y);
}

// V_k at a point: the share of G's part above the plane of `n` that no geometry blocks.
double lobe_visibility(const RayScene& rays, const dvec3& p, const dvec3& n, const SphericalGaussian& g) {
  constexpr int kStrata = 16;
  int above = 0, open = 0;
  const dvec3 origin = p + n * rays.ray_epsilon();
  for (int i = 0; i < kStrata; ++i)
    for (int j = 0; j < kStrata; ++j) {
      const dvec3 w = sg_direction(g, (i + 0.5) / kStrata, (j + 0.5) / kStrata);
      if (glm::dot(w, n) <= 0.0) continue;
      ++above;
      open += rays.unoccluded(origin, w);
    }
  return above ? double(open) / above : 1.0;
}

// The share of G's part above the plane of `shade` that also lies above the plane of `geo`
// (the facet: the reference blocks directions below the geometric surface).
double facet_share(const SphericalGaussian& g, const dvec3& shade, const dvec3& geo) {
  constexpr int kStrata = 24;
  int above = 0, both = 0;
  for (int i = 0; i < kStrata; ++i)
    for (int j = 0; j < kStrata; ++j) {
      const dvec3 w = sg_direction(g, (i + 0.5) / kStrata, (j + 0.5) / kStrata);
      if (glm::dot(w, shade) <= 0.0) continue;
      ++above;
      both += glm::dot(w, geo) > 0.0;
    }
  return above ? double(both) / above : 1.0;
}

// The weighting-table bundle of `scene` at the bench's settings, cached as a bundle file; `tables`: the
// fabric's tables when another scene's bundle holds them (then only the visibility is baked).
ShadingData bundle_for(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                             std::map<std::string, WeightingTables>& tables) {
  const int grid = env_int("WEFT_STUDY_GRID", 0), sdf = env_int("WEFT_STUDY_SDF", 128);
  const auto file = env_path("WEFT_STUDY_CACHE") /
                    (scene.name + "_" + fabrics.begin()->first + "_g" + std::to_string(grid) + "_sdf" +
                     std::to_string(sdf) + ".bundle");
  std::map<size_t, size_t> vertex_counts;
  for (size_t i = 0; i < scene.objects.size(); ++i) vertex_counts[i] = scene.objects[i].mesh.positions.size();
  if (std::filesystem::exists(file)) {
    ShadingData data = read_shading_data(bundle::BundleReader::read(file), vertex_counts);
    tables.insert(data.tables.begin(), data.tables.end());
    return data;
  }
  ShadingDataBakeOptions o;
  o.quiet = true;
  o.grid = grid;
  o.visibility.resolution = sdf;
  o.bake_tables = !tables.count(fabrics.begin()->first);
  std::fprintf(stderr, "baking %s ...\n", file.string().c_str());
  ShadingData data = bake_shading_data(scene, fabrics, o);
  if (o.bake_tables) tables.insert(data.tables.begin(), data.tables.end());
  else data.tables.emplace(fabrics.begin()->first, tables.at(fabrics.begin()->first));
  bundle::BundleWriter writer;
  add_shading_data_sections(writer, data);
  writer.write_file(file);
  return data;
}

constexpr int kVariants = 15;  // per SG and pixel, in this order:
enum Variant { ref_open, ref_occ, iw_open, iw_sdf, iw_exact, iwv_open, iwv_sdf, iwv_exact, iwv_mask, bq4_v, bq8_v, bq8_p, bq12_v, bq16_v, iw_geo };
// Broad lobes by quadrature of the model (bq*): SGs sharper than this are not integrated.
constexpr double kQuadratureUpTo = 16.0;

struct Study {
  std::FILE* budget;
  std::FILE* per_sg;
  std::FILE* quad;
  int width = env_int("WEFT_STUDY_WIDTH", 160), height = env_int("WEFT_STUDY_HEIGHT", 120);
  std::map<std::string, WeightingTables> tables_by_fabric;

  void run(const std::string& scene_name, const std::string& fabric_name, const std::string& env) {
    Scene scene = load_scene_named(scene_name, WEFT_SOURCE_ASSETS, fabric_name);
    std::map<std::string, Fabric> fabrics = test::dress_cloth(scene, fabric_name);
    const ShadingData data = bundle_for(scene, fabrics, tables_by_fabric);
    SgFitOptions fit;
    fit.count = 10;
    SgLighting sgs;
    for (const auto& g : fit_sgs(load_env(env, WEFT_SOURCE_ASSETS "/envmaps"), fit))
      if (std::max({g.amplitude.r, g.amplitude.g, g.amplitude.b}) > 0.0) sgs.push_back(g);
    const int K = int(sgs.size());

    // One reference per SG: the SG quadrature is a sum over SGs, so the sum is the bench's reference.
    ReferenceRenderOptions ro;
    ro.width = width, ro.height = height, ro.check_convergence = false;
    std::vector<std::unique_ptr<ReferenceRenderer>> occluded, open;
    for (const auto& g : sgs) {
      ReferenceLighting l;
      l.sgs = {g};
      occluded.push_back(std::make_unique<ReferenceRenderer>(scene, fabrics, l, ro));
      ro.occlusion = false;
      open.push_back(std::make_unique<ReferenceRenderer>(scene, fabrics, l, ro));
      ro.occlusion = true;
    }
    const RayScene rays(scene);
    const WeightingTables& tables = data.tables.at(fabric_name);
    const ClothBsdf bsdf(fabrics.at(fabric_name), tables.tangent_samples);
    std::map<size_t, SgVisibility> grids;
    for (const auto& [object, vis] : data.visibility)
      if (scene.objects[object].material == Material::cloth)
        grids.emplace(object, SgVisibility::compute(vis, scene.objects[object].mesh, sgs, true));

    // iwasaki at a point of triangle `tri` (bary `b`), SDF blended over `sdf_corners`; `vk`: V_k per SG or empty.
    auto iwasaki_at = [&](size_t object, const std::array<uint32_t, 3>& tri, dvec3 b, std::array<uint32_t, 3> sdf_corners,
                          dvec3 sdf_bary, int mode, int k, double vk) {
      const TriangleMesh& mesh = scene.objects[object].mesh;
      const test::MeshPoint m = test::mesh_point(mesh, tri, b);
      const dvec3 wo = glm::normalize(scene.camera.position - m.position);
      dvec3 n = glm::normalize(m.normal);
      if (glm::dot(n, wo) < 0) n = -n;
      const SurfaceFrame frame = SurfaceFrame::from_normal_warp(n, m.warp);
      SgLighting one{sgs[k]};
      IwasakiVisibility vis;
      const auto grid = grids.find(object);
      if (mode == 1 && grid != grids.end()) {
        vis.kappa = &*data.kappa;
        vis.sdf = [&](int, const ThreadFrame& tf, double theta, double phi, double& d, double& dt, double& dp) {
          const SdfSample s = sdf_in_sample_frame(grid->second, k, frame, sdf_corners, sdf_bary, tf, theta, phi);
          d = s.d, dt = s.d_dtheta, dp = s.d_dphi;
        };
      }
      if (mode == 2) one[0].amplitude *= vk;
      return iwasaki_radiance(bsdf, tables, frame, wo, one, mode == 1 && grid != grids.end() ? &vis : nullptr).radiance;
    };

    // Per vertex: V_k by rays from the vertex along its normal (toward the camera's side).
    std::map<size_t, std::vector<double>> vertex_vk;  // [vertex · K + k]
    for (size_t object = 0; object < scene.objects.size(); ++object) {
      if (scene.objects[object].material != Material::cloth) continue;
      const TriangleMesh& mesh = scene.objects[object].mesh;
      auto& vk = vertex_vk[object];
      vk.assign(mesh.positions.size() * K, 1.0);
#pragma omp parallel for schedule(dynamic, 16)
      for (size_t v = 0; v < mesh.positions.size(); ++v) {
        dvec3 n = glm::normalize(mesh.normals[v]);
        if (glm::dot(n, scene.camera.position - mesh.positions[v]) < 0) n = -n;
        for (int k = 0; k < K; ++k) vk[v * K + k] = lobe_visibility(rays, mesh.positions[v], n, sgs[k]);
      }
    }

    // Per vertex: V_k from the baked mask (runtime/visibility_mask.h), as iwasaki_vertex_mask reads it.
    const int mask_resolution = env_int("WEFT_STUDY_MASK", 64);
    std::map<size_t, SgVisibility> mask_vk;
    for (size_t object = 0; object < scene.objects.size(); ++object)
      if (scene.objects[object].material == Material::cloth)
        if (auto m = bake_visibility_mask(scene, object, mask_resolution)) {
          // What a lighting change costs: V_k from the mask against d, ∇d from the SDF's PCA.
          const auto t0 = std::chrono::steady_clock::now();
          mask_vk.emplace(object, SgVisibility::from_mask(*m, scene.objects[object].mesh, sgs));
          const auto t1 = std::chrono::steady_clock::now();
          SgVisibility::compute(data.visibility.at(object), scene.objects[object].mesh, sgs, true);
          const auto t2 = std::chrono::steady_clock::now();
          std::fprintf(stderr, "%s %s: V_k from the %d² mask %.1f ms, d and ∇d from the SDF %.1f ms (%zu vertices, %d SGs)\n",
                       scene_name.c_str(), env.c_str(), mask_resolution,
                       1e3 * std::chrono::duration<double>(t1 - t0).count(),
                       1e3 * std::chrono::duration<double>(t2 - t1).count(), scene.objects[object].mesh.positions.size(), K);
        }

    // Broad lobes by quadrature per vertex: the model on an M × 2M SG-warped grid (the reference's
    // own rule, fixed level), shadow rays from the vertex, at the runtime's tangent samples.
    std::map<size_t, std::vector<dvec3>> vertex_quad;  // [(vertex · K + k) · 4 + (M = 4, 8, 12, 16)]
    const auto tq0 = std::chrono::steady_clock::now();
    for (size_t object = 0; object < scene.objects.size(); ++object) {
      if (scene.objects[object].material != Material::cloth) continue;
      const TriangleMesh& mesh = scene.objects[object].mesh;
      auto& q = vertex_quad[object];
      q.assign(mesh.positions.size() * K * 4, dvec3(0));
#pragma omp parallel for schedule(dynamic, 16)
      for (size_t v = 0; v < mesh.positions.size(); ++v) {
        dvec3 n = glm::normalize(mesh.normals[v]);
        const dvec3 to_eye = scene.camera.position - mesh.positions[v];
        if (glm::dot(n, to_eye) < 0) n = -n;
        const SurfaceFrame frame = SurfaceFrame::from_normal_warp(n, mesh.warps[v]);
        const dvec3 origin = mesh.positions[v] + n * rays.ray_epsilon();
        SgQuadratureOptions o;
        o.parallel = false;
        o.visible = [&](const dvec3& w) { return rays.unoccluded(origin, w); };
        for (int k = 0; k < K; ++k) {
          if (sgs[k].sharpness >= kQuadratureUpTo) continue;
          for (int g = 0; g < 4; ++g) {
            o.fixed_polar = 4 * (g + 1);
            q[(v * K + k) * 4 + g] = integrate_sg_lighting(bsdf, frame, glm::normalize(to_eye), std::span(&sgs[k], 1), o).radiance;
          }
        }
      }
    }
    std::fprintf(stderr, "%s %s: broad quadrature per vertex %.1f s\n", scene_name.c_str(), env.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - tq0).count());

    const size_t pixels = size_t(width) * height;
    std::vector<dvec3> values(pixels * K * kVariants, dvec3(0));
    std::vector<bool> cloth(pixels, false);
    std::vector<double> pixel_vk(pixels * K, 1.0);
#pragma omp parallel for schedule(dynamic, 1)
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const dvec3 dir = camera_ray(scene.camera, width, height, x + 0.5, y + 0.5);
        const auto hit = rays.intersect(scene.camera.position, dir);
        if (!hit || scene.objects[hit->object].material != Material::cloth) continue;
        const size_t i = size_t(y) * width + x;
        cloth[i] = true;
        const auto& tri = scene.objects[hit->object].mesh.triangles[hit->triangle];
        const dvec3 bary(1 - hit->b1 - hit->b2, hit->b1, hit->b2);
        SurfacePoint s = rays.surface(*hit);
        if (glm::dot(s.geometric_normal, -dir) < 0) s.geometric_normal = -s.geometric_normal;
        const auto& vk = vertex_vk.at(hit->object);
        for (int k = 0; k < K; ++k) {
          dvec3* out = &values[(i * K + k) * kVariants];
          out[ref_open] = open[k]->shade(*hit, -dir, 0);
          out[ref_occ] = occluded[k]->shade(*hit, -dir, 0);
          const double v = pixel_vk[i * K + k] = lobe_visibility(rays, s.position, s.geometric_normal, sgs[k]);
          for (int mode = 0; mode < 3; ++mode) {
            out[iw_open + mode] = iwasaki_at(hit->object, tri, bary, {tri[0], tri[1], tri[2]}, bary, mode, k, v);
            if (mode == 1) {
              const test::MeshPoint m = test::mesh_point(scene.objects[hit->object].mesh, tri, bary);
              dvec3 n = glm::normalize(m.normal);
              if (glm::dot(n, -dir) < 0) n = -n;
              out[iw_geo] = out[iw_sdf] * facet_share(sgs[k], n, s.geometric_normal);
            }
            dvec3 sum(0);
            for (int c = 0; c < 3; ++c) {
              dvec3 one(0);
              one[c] = 1;
              sum += bary[c] * iwasaki_at(hit->object, tri, one, {tri[c], tri[c], tri[c]}, dvec3(1, 0, 0), mode, k,
                                          vk[tri[c] * K + k]);
            }
            out[iwv_open + mode] = sum;
          }
          const auto mk = mask_vk.find(hit->object);
          dvec3 sum(0);
          for (int c = 0; c < 3; ++c) {
            dvec3 one(0);
            one[c] = 1;
            sum += bary[c] * iwasaki_at(hit->object, tri, one, {tri[c], tri[c], tri[c]}, dvec3(1, 0, 0), 2, k,
                                        mk == mask_vk.end() ? 1.0 : mk->second.at(tri[c], k).x);
          }
          out[iwv_mask] = sum;
          if (sgs[k].sharpness < kQuadratureUpTo) {
            const auto& q = vertex_quad.at(hit->object);
            for (int c = 0; c < 3; ++c) {
              out[bq4_v] += bary[c] * q[(tri[c] * K + k) * 4 + 0];
              out[bq8_v] += bary[c] * q[(tri[c] * K + k) * 4 + 1];
              out[bq12_v] += bary[c] * q[(tri[c] * K + k) * 4 + 2];
              out[bq16_v] += bary[c] * q[(tri[c] * K + k) * 4 + 3];
            }
            const test::MeshPoint m = test::mesh_point(scene.objects[hit->object].mesh, tri, bary);
            dvec3 n = glm::normalize(m.normal);
            if (glm::dot(n, -dir) < 0) n = -n;
            const dvec3 origin = s.position + s.geometric_normal * rays.ray_epsilon();
            SgQuadratureOptions o;
            o.parallel = false;
            o.fixed_polar = 8;
            o.visible = [&](const dvec3& w) { return glm::dot(w, s.geometric_normal) > 0 && rays.unoccluded(origin, w); };
            out[bq8_p] = integrate_sg_lighting(bsdf, SurfaceFrame::from_normal_warp(n, m.warp), -dir, std::span(&sgs[k], 1), o).radiance;
          }
        }
      }

    // Images summed over SGs (or one SG's alone), errors as the bench measures them (masked_error).
    auto image = [&](int variant, int k) {
      Image im(width, height);
      for (size_t i = 0; i < pixels; ++i)
        for (int j = 0; j < K; ++j)
          if (k < 0 || j == k) im.pixels[i] += values[(i * K + j) * kVariants + variant];
      return im;
    };
    const Image r_open = image(ref_open, -1), r_occ = image(ref_occ, -1);
    auto err = [&](int variant, const Image& ref) { return bench::masked_error(image(variant, -1), ref, cloth); };
    const auto vis_effect = bench::masked_error(r_open, r_occ, cloth);
    std::fprintf(budget, "%s,%s,%s,%d,%d,%zu,%.4f,%.4f", scene_name.c_str(), fabric_name.c_str(), env.c_str(), width,
                 height, vis_effect.pixels, vis_effect.relative_rmse, vis_effect.brightness_ratio);
    for (int v : {iw_open, iw_sdf, iw_exact, iwv_open, iwv_sdf, iwv_exact, iwv_mask}) {
      const auto e = err(v, v == iw_open || v == iwv_open ? r_open : r_occ);
      std::fprintf(budget, ",%.4f,%.4f", e.relative_rmse, e.brightness_ratio);
    }
    std::fprintf(budget, "\n");
    std::fflush(budget);

    // Narrow SGs from one variant, broad ones (λ < λ_b) from a quadrature variant.
    auto split = [&](int narrow, int broad, double lambda_b) {
      Image im(width, height);
      for (size_t i = 0; i < pixels; ++i)
        for (int j = 0; j < K; ++j)
          im.pixels[i] += values[(i * K + j) * kVariants + (sgs[j].sharpness < lambda_b ? broad : narrow)];
      return bench::masked_error(im, r_occ, cloth);
    };
    const std::pair<const char*, std::pair<int, int>> combos[] = {
        {"pixel_sdf+vertex_quad4", {iw_sdf, bq4_v}},     {"pixel_sdf+vertex_quad8", {iw_sdf, bq8_v}},
        {"pixel_sdf+pixel_quad8", {iw_sdf, bq8_p}},
        {"pixel_sdf_facet+vertex_quad8", {iw_geo, bq8_v}},
        {"pixel_sdf+vertex_quad12", {iw_sdf, bq12_v}},   {"pixel_sdf+vertex_quad16", {iw_sdf, bq16_v}},      {"pixel_exact+vertex_quad8", {iw_exact, bq8_v}},
        {"vertex_sdf+vertex_quad4", {iwv_sdf, bq4_v}},   {"vertex_sdf+vertex_quad8", {iwv_sdf, bq8_v}},
        {"vertex_mask+vertex_quad8", {iwv_mask, bq8_v}}, {"vertex_exact+vertex_quad8", {iwv_exact, bq8_v}}};
    for (double lambda_b : {2.0, 4.0, 8.0, 16.0})
      for (const auto& [name, c] : combos) {
        const auto e = split(c.first, c.second, lambda_b);
        std::fprintf(quad, "%s,%s,%s,%s,%g,%.4f,%.4f\n", scene_name.c_str(), fabric_name.c_str(), env.c_str(), name,
                     lambda_b, e.relative_rmse, e.brightness_ratio);
      }
    std::fflush(quad);

    // Per SG: its share of the reference and its own error, relative to the whole image's mean.
    double mean_occ = 0, mean_open = 0;
    size_t n = 0;
    for (size_t i = 0; i < pixels; ++i)
      if (cloth[i]) {
        mean_occ += r_occ.pixels[i].r + r_occ.pixels[i].g + r_occ.pixels[i].b;
        mean_open += r_open.pixels[i].r + r_open.pixels[i].g + r_open.pixels[i].b;
        ++n;
      }
    mean_occ /= 3.0 * n, mean_open /= 3.0 * n;
    for (int k = 0; k < K; ++k) {
      const dvec3& a = sgs[k].axis;
      double vk_mean = 0;
      for (size_t i = 0; i < pixels; ++i)
        if (cloth[i]) vk_mean += pixel_vk[i * K + k];
      std::fprintf(per_sg, "%s,%s,%s,%d,%.3f,%.2f,%.3f,%.3f", scene_name.c_str(), fabric_name.c_str(), env.c_str(), k,
                   sgs[k].sharpness, glm::degrees(std::asin(std::clamp(a.z, -1.0, 1.0))),
                   (sgs[k].amplitude.r + sgs[k].amplitude.g + sgs[k].amplitude.b) / 3, vk_mean / n);
      // Share of the reference, then RMSE and bias of this SG's term, over the full image's mean.
      for (int v : {iw_open, iw_sdf, iw_exact, iwv_sdf, iwv_exact, iwv_mask}) {
        const int rv = v == iw_open ? ref_open : ref_occ;
        const double mean = v == iw_open ? mean_open : mean_occ;
        double se = 0, sr = 0, sx = 0;
        for (size_t i = 0; i < pixels; ++i)
          if (cloth[i]) {
            const dvec3 r = values[(i * K + k) * kVariants + rv], x = values[(i * K + k) * kVariants + v];
            se += glm::dot(x - r, x - r);
            sr += r.r + r.g + r.b;
            sx += x.r + x.g + x.b;
          }
        if (v == iw_open) std::fprintf(per_sg, ",%.4f", sr / (3.0 * n) / mean);
        if (v == iw_sdf) std::fprintf(per_sg, ",%.4f", sr / (3.0 * n) / mean);
        std::fprintf(per_sg, ",%.4f,%+.4f", std::sqrt(se / (3.0 * n)) / mean, (sx - sr) / (3.0 * n) / mean);
      }
      std::fprintf(per_sg, "\n");
    }
    std::fflush(per_sg);
    std::fprintf(stderr, "%s/%s/%s done\n", scene_name.c_str(), fabric_name.c_str(), env.c_str());
  }
};

TEST(Study, VisibilityBudget) {
  const auto out = env_path("WEFT_STUDY_OUT");
  Study s;
  s.budget = std::fopen((out / "budget.csv").string().c_str(), "w");
  s.per_sg = std::fopen((out / "per_sg.csv").string().c_str(), "w");
  s.quad = std::fopen((out / "quad.csv").string().c_str(), "w");
  ASSERT_TRUE(s.budget && s.per_sg && s.quad);
  std::fprintf(s.quad, "scene,fabric,env,variant,broad_below_lambda,relative_rmse,brightness_ratio\n");
  std::fprintf(s.budget,
               "scene,fabric,env,width,height,cloth_pixels,occlusion_effect,open_over_occluded,"
               "open_err,open_ratio,sdf_err,sdf_ratio,exact_err,exact_ratio,"
               "vertex_open_err,vertex_open_ratio,vertex_sdf_err,vertex_sdf_ratio,vertex_exact_err,vertex_exact_ratio,"
               "vertex_mask_err,vertex_mask_ratio\n");
  std::fprintf(s.per_sg,
               "scene,fabric,env,sg,lambda,elevation_deg,amplitude,mean_vk,open_share,open_rmse,open_bias,occ_share,"
               "sdf_rmse,sdf_bias,exact_rmse,exact_bias,vertex_sdf_rmse,vertex_sdf_bias,vertex_exact_rmse,vertex_exact_bias,"
               "vertex_mask_rmse,vertex_mask_bias\n");
  const char* only = std::getenv("WEFT_STUDY_CASES");  // e.g. "pillow" to run one scene
  // $WEFT_STUDY_RUNS: "scene/fabric/env;..." in place of the four linen cases.
  std::vector<std::array<std::string, 3>> runs;
  if (const char* r = std::getenv("WEFT_STUDY_RUNS")) {
    std::string list = r;
    for (size_t a = 0; a < list.size();) {
      size_t b = list.find(';', a);
      if (b == std::string::npos) b = list.size();
      const std::string item = list.substr(a, b - a);
      const size_t s1 = item.find('/'), s2 = item.find('/', s1 + 1);
      if (s1 != std::string::npos && s2 != std::string::npos)
        runs.push_back({item.substr(0, s1), item.substr(s1 + 1, s2 - s1 - 1), item.substr(s2 + 1)});
      a = b + 1;
    }
  } else {
    for (const std::string scene : {"pillow", "drape"})
      for (const std::string env : {"sky:elev=5", "sky:elev=20"})
        if (!only || std::string(only).find(scene) != std::string::npos) runs.push_back({scene, "linen_plain", env});
  }
  for (const auto& [scene, fabric, env] : runs) s.run(scene, fabric, env);
  std::fclose(s.quad);
  std::fclose(s.budget);
  std::fclose(s.per_sg);
}

}  // namespace
