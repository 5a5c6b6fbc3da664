// Accuracy of textured cloth against the reference (issue 35, item 1: "within 1 point of the
// untextured figure on the same view"). The swatch under a sun and a sky, drawn by the per-pixel
// rung (iwasaki) and ray traced by the reference (supersampled, so its pixels average a texture's
// footprint as the GPU's mip levels do): a checker baseColorTexture and a tilted bump normal map
// must each keep the relative RMSE within 1 percentage point of the untextured one; a flat normal
// map must draw the image drawn without one. The same for the per-vertex rungs' normal map (its
// per-pixel ratio, methods/iwasaki/vertex_normal_map.h), where a flat map draws exactly the
// unmapped image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "gpu/scene_renderer.h"
#include "measure/image_metrics.h"
#include "methods/iwasaki/iwasaki.h"
#include "methods/registry.h"
#include "reference/scene_render.h"
#include "scene/scene_file.h"
#include "support/parity_bake_settings.h"

using namespace weft;
using glm::dvec3;

namespace {

constexpr int kWidth = 64, kHeight = 48;

SgLighting test_lights() {
  SgLighting l;
  l.push_back({glm::normalize(dvec3(0.3, -0.5, 0.8)), 60.0, dvec3(6.0, 5.5, 5.0)});
  l.push_back({glm::normalize(dvec3(-0.6, 0.2, 0.7)), 4.0, dvec3(0.6, 0.7, 0.9)});
  return l;
}

std::shared_ptr<TextureImage> blank(int n) {
  auto t = std::make_shared<TextureImage>();
  t->width = t->height = n;
  t->rgba.assign(size_t(n) * n * 4, 255);
  return t;
}

// Two colours in 4×4-texel squares (a plaid's sharp edges).
std::shared_ptr<const TextureImage> checker() {
  auto t = blank(16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      uint8_t* p = &t->rgba[(size_t(y) * 16 + x) * 4];
      const bool dark = ((x / 4) + (y / 4)) % 2 == 1;
      p[0] = dark ? 90 : 240, p[1] = dark ? 60 : 220, p[2] = dark ? 40 : 200;
    }
  return t;
}

// A normal map: flat (128, 128, 255), or smooth bumps tilting up to ~25° along and across.
std::shared_ptr<const TextureImage> normal_map(bool tilted) {
  constexpr int n = 64;
  auto t = blank(n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      uint8_t* p = &t->rgba[(size_t(y) * n + x) * 4];
      const double a = 2 * 3.14159265358979 * x / n, b = 2 * 3.14159265358979 * y / n;
      const dvec3 d = tilted ? glm::normalize(dvec3(0.45 * std::sin(a), 0.3 * std::cos(b), 1.0)) : dvec3(0, 0, 1);
      p[0] = uint8_t(std::lround(127.5 + 127.5 * d.x)), p[1] = uint8_t(std::lround(127.5 + 127.5 * d.y));
      p[2] = uint8_t(std::lround(127.5 + 127.5 * d.z));
    }
  return t;
}

enum class Look { plain, checker, flat_normals, bumps };

Scene swatch(Look look) {
  Scene scene = load_scene_preset("swatch", WEFT_SOURCE_ASSETS "/scenes");
  for (auto& o : scene.objects)
    if (o.is_cloth()) {
      if (look == Look::checker) {
        o.thread_maps[0] = ThreadMap{checker(), "checker", {{0.0, 0.0}, {2.0, 2.0}, 0.0}};
        o.thread_maps[1] = o.thread_maps[0];
      }
      if (look == Look::flat_normals || look == Look::bumps)
        o.normal_map = NormalMap{ThreadMap{normal_map(look == Look::bumps), "normals", {{0.0, 0.0}, {1.0, 1.0}, 0.0}}, 1.0};
    }
  return scene;
}

struct Drawn {
  Image gpu;
  ReferenceRenderResult reference;
  double error = 0.0;  // relative RMSE over the cloth pixels
};

Fabric swatch_fabric(const Scene& scene) {
  return object_base_fabric(scene.objects[0], load_fabric_preset(scene.objects[0].fabric, WEFT_SOURCE_ASSETS "/fabrics"));
}

Image draw_gpu(const Scene& scene, const std::string& method) {
  const Fabric fabric = swatch_fabric(scene);
  // One bake of the tables for every draw (they depend on the fabric alone).
  static std::map<std::string, std::shared_ptr<ShadingData>> baked;
  auto& data = baked[fabric.name];
  if (!data) {
    data = std::make_shared<ShadingData>();
    data->tables.emplace(fabric.name, bake_weighting_tables(fabric, test::parity_bake_settings()));
  }
  gpu::EglContext ctx = gpu::EglContext::headless();
  gpu::SceneRenderer renderer(scene, {fabric}, methods::method(method), 16, data);
  EXPECT_TRUE(renderer.warnings().empty()) << renderer.warnings().front();
  renderer.set_lighting(test_lights());
  gpu::OffscreenTarget target(kWidth, kHeight);
  target.bind();
  renderer.draw(scene.camera, kWidth, kHeight);
  return gpu::read_linear_image(kWidth, kHeight);
}

// The reference of one look, rendered once for every method drawn against it.
const ReferenceRenderResult& reference_of(Look look) {
  static std::map<Look, ReferenceRenderResult> rendered;
  auto it = rendered.find(look);
  if (it != rendered.end()) return it->second;
  const Scene scene = swatch(look);
  const std::string preset = scene.objects[0].fabric;
  ReferenceLighting lighting;
  lighting.sgs = test_lights();
  ReferenceRenderOptions ro;
  ro.width = kWidth, ro.height = kHeight;
  ro.check_convergence = false;
  ro.supersample = 2;
  ro.tangent_samples = 16;
  ro.sg_grid = 6;
  const ReferenceRenderer reference(scene, {{preset, load_fabric_preset(preset, WEFT_SOURCE_ASSETS "/fabrics")}}, lighting, ro);
  return rendered.emplace(look, reference.render()).first->second;
}

Drawn draw(Look look, bool with_reference = true, const std::string& method = "iwasaki") {
  Drawn d;
  d.gpu = draw_gpu(swatch(look), method);
  if (!with_reference) return d;
  d.reference = reference_of(look);
  d.error = bench::cloth_error(d.gpu, d.reference.image, d.reference.kinds).relative_rmse;
  return d;
}

double relative_difference(const Image& a, const Image& b) {
  double diff = 0.0, mean = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      diff += glm::dot(a.at(x, y) - b.at(x, y), a.at(x, y) - b.at(x, y));
      mean += glm::length(b.at(x, y));
    }
  const double n = double(a.width) * a.height;
  return std::sqrt(diff / n) / (mean / n);
}

}  // namespace

TEST(TexturedAccuracy, TexturesAndNormalMapsKeepTheRungsError) {
  const Drawn plain = draw(Look::plain), textured = draw(Look::checker), bumps = draw(Look::bumps);
  std::printf("relative RMSE vs reference (iwasaki, swatch): untextured %.4f, checker %.4f, bump normal map %.4f\n",
              plain.error, textured.error, bumps.error);
  EXPECT_LE(textured.error, plain.error + 0.01);
  EXPECT_LE(bumps.error, plain.error + 0.01);
  // The bumps show: the image moves well beyond the rung's own error.
  const double moved = relative_difference(bumps.gpu, plain.gpu);
  std::printf("bump normal map changes the image by %.4f (relative RMS)\n", moved);
  EXPECT_GT(moved, 0.05);
  const double moved_reference = relative_difference(bumps.reference.image, plain.reference.image);
  EXPECT_GT(moved_reference, 0.05);
  // The per-vertex rungs (the kiosk's auto among them) draw the bump map by their per-pixel ratio:
  // within 1 point of their own untextured error, and visibly bumped. Here, against the references
  // rendered above (one process).
  for (const char* method : {"iwasaki_vertex", "iwasaki_vertex_quadrature"}) {
    const Drawn vertex_plain = draw(Look::plain, true, method), vertex_bumps = draw(Look::bumps, true, method);
    const double vertex_moved = relative_difference(vertex_bumps.gpu, vertex_plain.gpu);
    std::printf("relative RMSE vs reference (%s, swatch): untextured %.4f, bump normal map %.4f; the map changes the "
                "image by %.4f\n",
                method, vertex_plain.error, vertex_bumps.error, vertex_moved);
    EXPECT_LE(vertex_bumps.error, vertex_plain.error + 0.01) << method;
    EXPECT_GT(vertex_moved, 0.05) << method;
  }
}

TEST(TexturedAccuracy, FlatNormalMapDrawsTheUnmappedImage) {
  const Drawn plain = draw(Look::plain, false), flat = draw(Look::flat_normals, false);
  const double d = relative_difference(flat.gpu, plain.gpu);
  std::printf("flat normal map vs none: %.2e (relative RMS)\n", d);
  EXPECT_LT(d, 1e-3);
}

TEST(TexturedAccuracy, FlatNormalMapOnThePerVertexRungsDrawsExactlyTheUnmappedImage) {
  for (const char* method : {"iwasaki_vertex", "iwasaki_vertex_quadrature"}) {
    const Drawn plain = draw(Look::plain, false, method), flat = draw(Look::flat_normals, false, method);
    double worst = 0.0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) worst = std::max(worst, glm::length(flat.gpu.at(x, y) - plain.gpu.at(x, y)));
    EXPECT_EQ(worst, 0.0) << method;
  }
}
