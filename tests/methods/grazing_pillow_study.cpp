// Point study on a scene (bench label, no assertions): what shades the sharp SGs low over the
// horizon wrong on a curved cloth (pillow / linen / the bundled studio: docs/research/iwasaki.md, "A sharp lobe
// low over the horizon"). Per cloth pixel and per SG with λ ≥ 16, occlusion off on both sides (the
// facet's plane still cuts both), for N tangent samples per thread in $WEFT_STUDY_SAMPLES
// (default "3,6,12"), tables at grid $WEFT_STUDY_GRID (default 32; ω_o at $WEFT_STUDY_WO_GRID when set):
//   ref      the reference (N_j = 32);
//   model_N  the model itself at N samples (the reference's quadrature at N): what the samples cost;
//   iw_N     iwasaki at N samples (tables baked at N, grid $WEFT_STUDY_GRID, default 32), with the
//            facet's factor as the per-pixel rungs apply it: what the closed form adds.
// Errors are RMSE over the cloth pixels divided by the mean of the whole reference image (points of
// the bench's relative RMSE), with the mean bias. Prints CSV; writes each SG's images (EXR) and
// signed error maps (PNG, red: too bright) to $WEFT_STUDY_OUT when set.
// $WEFT_STUDY_CASE: "scene/fabric/env" (default pillow/linen_plain/studio).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"
#include "image/image.h"
#include "lighting/env_spec.h"
#include "lighting/sg_fit.h"
#include "methods/iwasaki/iwasaki.h"
#include "reference/ray_scene.h"
#include "reference/scene_render.h"
#include "scene/scene_file.h"
#include "support/ray_pixels.h"
#include "support/scene_case.h"

using namespace weft;

namespace {

std::string env_or(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

std::vector<int> sample_counts() {
  std::vector<int> out;
  std::stringstream s(env_or("WEFT_STUDY_SAMPLES", "3,6,12"));
  for (std::string item; std::getline(s, item, ',');) out.push_back(std::stoi(item));
  return out;
}

double elevation_deg(const SphericalGaussian& g) {
  return glm::degrees(std::asin(std::clamp(glm::normalize(g.axis).z, -1.0, 1.0)));
}

// Signed error (x − r) as colour: red where x is brighter, blue where darker, full at ±scale.
Image error_map(const std::vector<dvec3>& x, const std::vector<dvec3>& r, int width, int height, double scale) {
  Image out(width, height);
  for (size_t i = 0; i < x.size(); ++i) {
    const double e = (x[i].g - r[i].g) / scale;
    out.pixels[i] = e > 0 ? dvec3(std::min(e, 1.0), 0, 0) : dvec3(0, 0, std::min(-e, 1.0));
  }
  return out;
}

}  // namespace

TEST(Study, GrazingSharpLobeOnScene) {
  const std::string spec = env_or("WEFT_STUDY_CASE", "pillow/linen_plain/studio");
  const auto s1 = spec.find('/'), s2 = spec.rfind('/');
  const std::string scene_name = spec.substr(0, s1), fabric_name = spec.substr(s1 + 1, s2 - s1 - 1),
                    env = spec.substr(s2 + 1);
  const int width = std::atoi(env_or("WEFT_STUDY_WIDTH", "160").c_str()),
            height = std::atoi(env_or("WEFT_STUDY_HEIGHT", "120").c_str()),
            grid = std::atoi(env_or("WEFT_STUDY_GRID", "32").c_str()),
            wo_grid = std::atoi(env_or("WEFT_STUDY_WO_GRID", "0").c_str());
  const std::string out_dir = env_or("WEFT_STUDY_OUT", "");

  Scene scene = load_scene_named(scene_name, WEFT_SOURCE_ASSETS, fabric_name);
  const std::map<std::string, Fabric> fabrics = test::dress_cloth(scene, fabric_name);
  const Fabric& fabric = fabrics.at(fabric_name);
  SgFitOptions fit;
  fit.count = 10;
  SgLighting sgs;
  for (const auto& g : fit_sgs(load_env(env, WEFT_SOURCE_ASSETS "/envmaps"), fit))
    if (std::max({g.amplitude.r, g.amplitude.g, g.amplitude.b}) > 0.0) sgs.push_back(g);

  const RayScene rays(scene);
  const std::vector<int> counts = sample_counts();
  ReferenceRenderOptions ro;
  ro.width = width, ro.height = height, ro.check_convergence = false, ro.occlusion = false;

  // The whole image's reference mean: the bench's normaliser.
  const size_t pixels = size_t(width) * height;
  std::vector<int> hit_object(pixels, -1);
  std::vector<RayHit> hits(pixels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const dvec3 dir = camera_ray(scene.camera, width, height, x + 0.5, y + 0.5);
      if (auto hit = rays.intersect(scene.camera.position, dir); hit && scene.objects[hit->object].material == Material::cloth) {
        hit_object[size_t(y) * width + x] = int(hit->object);
        hits[size_t(y) * width + x] = *hit;
      }
    }
  std::vector<std::vector<dvec3>> ref(sgs.size(), std::vector<dvec3>(pixels, dvec3(0)));
  double total = 0;
  size_t cloth = 0;
  for (size_t k = 0; k < sgs.size(); ++k) {
    ReferenceLighting l;
    l.sgs = {sgs[k]};
    const ReferenceRenderer r(scene, fabrics, l, ro);
#pragma omp parallel for schedule(dynamic, 1)
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const size_t i = size_t(y) * width + x;
        if (hit_object[i] < 0) continue;
        ref[k][i] = r.shade(hits[i], -camera_ray(scene.camera, width, height, x + 0.5, y + 0.5), 0);
      }
  }
  for (size_t i = 0; i < pixels; ++i)
    if (hit_object[i] >= 0) {
      dvec3 sum(0);
      for (const auto& img : ref) sum += img[i];
      total += glm::length(sum), ++cloth;
    }
  const double mean = total / double(cloth);

  auto rmse_bias = [&](const std::vector<dvec3>& x, const std::vector<dvec3>& r, double& bias) {
    double se = 0, b = 0;
    for (size_t i = 0; i < pixels; ++i)
      if (hit_object[i] >= 0) {
        const dvec3 d = x[i] - r[i];
        se += glm::dot(d, d), b += (d.r + d.g + d.b) / 3;
      }
    bias = b / double(cloth) / mean;
    return std::sqrt(se / double(cloth)) / mean;
  };

  std::printf("scene,fabric,env,sg,lambda,elevation_deg,share,samples,model_rmse,model_bias,iw_rmse,iw_bias,iw_vs_model_rmse\n");
  for (int n : counts) {
    BakeSettings settings;
    settings.tangent_samples = {n, n};
    if (grid > 0) settings.xi_resolution = settings.wo_resolution = settings.wi_resolution = grid;
    if (wo_grid > 0) settings.wo_resolution = wo_grid;
    std::fprintf(stderr, "baking %s tables at %d+%d samples, grid %d ...\n", fabric_name.c_str(), n, n, grid);
    const WeightingTables tables = bake_weighting_tables(fabric, settings);
    const ClothBsdf bsdf(fabric, settings.tangent_samples);
    ReferenceRenderOptions mo = ro;
    mo.tangent_samples = n;
    for (size_t k = 0; k < sgs.size(); ++k) {
      if (sgs[k].sharpness < 16.0) continue;
      ReferenceLighting l;
      l.sgs = {sgs[k]};
      const ReferenceRenderer model_r(scene, fabrics, l, mo);
      std::vector<dvec3> model(pixels, dvec3(0)), iw(pixels, dvec3(0));
      std::vector<glm::dvec4> geometry(pixels, glm::dvec4(0));  // n·ξ, n·ω_o, cos of their azimuths' difference, ξ·n_g
#pragma omp parallel for schedule(dynamic, 1)
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          const size_t i = size_t(y) * width + x;
          if (hit_object[i] < 0) continue;
          const dvec3 dir = camera_ray(scene.camera, width, height, x + 0.5, y + 0.5);
          model[i] = model_r.shade(hits[i], -dir, 0);
          const RayHit& hit = hits[i];
          const TriangleMesh& mesh = scene.objects[hit.object].mesh;
          const dvec3 bary(1 - hit.b1 - hit.b2, hit.b1, hit.b2);
          const test::MeshPoint m = test::mesh_point(mesh, mesh.triangles[hit.triangle], bary);
          dvec3 nrm = glm::normalize(m.normal);
          if (glm::dot(nrm, -dir) < 0) nrm = -nrm;
          SurfacePoint s = rays.surface(hit);
          if (glm::dot(s.geometric_normal, -dir) < 0) s.geometric_normal = -s.geometric_normal;
          SgLighting one{sgs[k]};
          one[0].amplitude *= facet_horizon_factor(sgs[k], nrm, s.geometric_normal);
          const dvec3 xi = glm::normalize(sgs[k].axis), wo = -dir;
          const dvec3 xt = xi - glm::dot(xi, nrm) * nrm, ot = wo - glm::dot(wo, nrm) * nrm;
          const double lt = glm::length(xt) * glm::length(ot);
          geometry[i] = glm::dvec4(glm::dot(nrm, xi), glm::dot(nrm, wo), lt > 0 ? glm::dot(xt, ot) / lt : 1.0,
                              glm::dot(xi, s.geometric_normal));
          iw[i] = iwasaki_radiance(bsdf, tables, SurfaceFrame::from_normal_warp(nrm, m.warp), -dir, one).radiance;
        }
      double mb = 0, ib = 0, unused = 0;
      const double me = rmse_bias(model, ref[k], mb), ie = rmse_bias(iw, ref[k], ib), im = rmse_bias(iw, model, unused);
      double share = 0;
      for (size_t i = 0; i < pixels; ++i)
        if (hit_object[i] >= 0) share += glm::length(ref[k][i]);
      std::printf("%s,%s,%s,%zu,%.1f,%.2f,%.4f,%d,%.4f,%+.4f,%.4f,%+.4f,%.4f\n", scene_name.c_str(), fabric_name.c_str(),
                  env.c_str(), k, sgs[k].sharpness, elevation_deg(sgs[k]), share / total, n, me, mb, ie, ib, im);
      std::fflush(stdout);
      if (!out_dir.empty()) {
        std::filesystem::create_directories(out_dir);
        const std::string stem = out_dir + "/sg" + std::to_string(k) + "_";
        Image a(width, height), b(width, height), c(width, height);
        a.pixels = ref[k], b.pixels = model, c.pixels = iw;
        if (n == counts.front()) write_exr(a, stem + "ref.exr");
        write_exr(b, stem + "model" + std::to_string(n) + ".exr");
        write_exr(c, stem + "iw" + std::to_string(n) + ".exr");
        const double scale = 0.5 * mean;
        write_png(error_map(model, ref[k], width, height, scale), stem + "model" + std::to_string(n) + "_err.png");
        write_png(error_map(iw, ref[k], width, height, scale), stem + "iw" + std::to_string(n) + "_err.png");
        std::FILE* f = std::fopen((stem + "pixels" + std::to_string(n) + ".csv").c_str(), "w");
        std::fprintf(f, "x,y,ref,model,iw,n_xi,n_wo,cos_dphi,ng_xi\n");
        for (size_t i = 0; i < pixels; ++i)
          if (hit_object[i] >= 0)
            std::fprintf(f, "%zu,%zu,%.5g,%.5g,%.5g,%.4f,%.4f,%.4f,%.4f\n", i % width, i / width, ref[k][i].g, model[i].g,
                         iw[i].g, geometry[i].x, geometry[i].y, geometry[i].z, geometry[i].w);
        std::fclose(f);
      }
    }
  }
}
