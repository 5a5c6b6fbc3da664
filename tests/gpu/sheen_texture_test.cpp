// The `sheen` rung (the Filament-class baseline) on a textured cloth: a texture's texels multiply
// each thread's part of its Lambert colour, and a normal map tilts its normal (plain normal
// mapping: sheen has no threads to turn). Checked against independent draws: a one-colour texture
// per thread must draw what the untextured fabric recoloured by those colours draws, and a
// uniformly tilted normal map on the flat swatch what the swatch whose vertex normals are tilted
// alike draws.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "core/fabric.h"
#include "core/normal_map_frame.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "gpu/scene_renderer.h"
#include "methods/registry.h"
#include "scene/scene_file.h"

using namespace weft;
using glm::dvec3;

namespace {

constexpr int kWidth = 48, kHeight = 36;

SgLighting lights() {
  return {SphericalGaussian{glm::normalize(dvec3(0.3, -0.5, 0.8)), 60.0, dvec3(6.0, 5.5, 5.0)},
          SphericalGaussian{glm::normalize(dvec3(-0.6, 0.2, 0.7)), 4.0, dvec3(0.6, 0.7, 0.9)}};
}

// A 4×4 image of one 8-bit colour.
std::shared_ptr<const TextureImage> one_colour(uint8_t r, uint8_t g, uint8_t b) {
  auto t = std::make_shared<TextureImage>();
  t->width = t->height = 4;
  for (int i = 0; i < 16; ++i) t->rgba.insert(t->rgba.end(), {r, g, b, 255});
  return t;
}

Fabric fabric_of(const Scene& scene) {
  return object_base_fabric(scene.objects[0], load_fabric_preset(scene.objects[0].fabric, WEFT_SOURCE_ASSETS "/fabrics"));
}

Image draw_sheen(const Scene& scene, const Fabric& fabric) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  gpu::SceneRenderer renderer(scene, {fabric}, methods::method("sheen"), 16, nullptr);
  EXPECT_TRUE(renderer.warnings().empty()) << renderer.warnings().front();
  renderer.set_lighting(lights());
  gpu::OffscreenTarget target(kWidth, kHeight);
  target.bind();
  renderer.draw(scene.camera, kWidth, kHeight);
  return gpu::read_linear_image(kWidth, kHeight);
}

// Largest per-pixel difference over the image's largest channel value.
double worst_difference(const Image& a, const Image& b) {
  double worst = 0.0, top = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const dvec3 d = glm::abs(dvec3(a.at(x, y)) - dvec3(b.at(x, y)));
      worst = std::max({worst, d.r, d.g, d.b});
      top = std::max({top, double(b.at(x, y).r), double(b.at(x, y).g), double(b.at(x, y).b)});
    }
  return worst / top;
}

}  // namespace

TEST(SheenTextures, EachThreadsTexelTintsItsPartOfTheColour) {
  const Scene plain = load_scene_preset("swatch", WEFT_SOURCE_ASSETS "/scenes");
  Scene textured = plain;
  textured.objects[0].thread_maps[0] = ThreadMap{one_colour(220, 120, 60), "warp", {}};
  textured.objects[0].thread_maps[1] = ThreadMap{one_colour(70, 150, 230), "weft", {}};
  // The expectation: the untextured fabric with each thread's albedo times its texel (sRGB decoded).
  Fabric recoloured = fabric_of(plain);
  for (int j = 0; j < 2; ++j) recoloured.threads[j].albedo *= thread_tint(textured.objects[0], j, {0.5, 0.5});
  const Image drawn = draw_sheen(textured, fabric_of(textured));
  const Image expected = draw_sheen(plain, recoloured);
  const Image untextured = draw_sheen(plain, fabric_of(plain));
  const double d = worst_difference(drawn, expected), moved = worst_difference(untextured, expected);
  std::printf("sheen, texels vs recoloured fabric: worst %.2e of the peak; the texture moves the image by %.2f\n", d, moved);
  EXPECT_LT(d, 2e-3);
  EXPECT_GT(moved, 0.05);
}

TEST(SheenTextures, ANormalMapTiltsTheNormal) {
  const Scene plain = load_scene_preset("swatch", WEFT_SOURCE_ASSETS "/scenes");
  const uint8_t code[3] = {175, 95, 225};
  Scene mapped = plain;
  mapped.objects[0].normal_map = NormalMap{ThreadMap{one_colour(code[0], code[1], code[2]), "normals", {}}, 1.0};
  // The expectation: the mesh's own normals turned to the map's n′ (the swatch's warps give x).
  Scene tilted = plain;
  const dvec3 t = tangent_space_normal(dvec3(code[0], code[1], code[2]) / 255.0, 1.0);
  TriangleMesh& m = tilted.objects[0].mesh;
  for (size_t i = 0; i < m.normals.size(); ++i)
    m.normals[i] = normal_mapped_frame(SurfaceFrame::from_normal_warp(m.normals[i], m.warps[i]), t).n;
  const Fabric fabric = fabric_of(plain);
  const Image drawn = draw_sheen(mapped, fabric), expected = draw_sheen(tilted, fabric), flat = draw_sheen(plain, fabric);
  const double d = worst_difference(drawn, expected), moved = worst_difference(flat, expected);
  std::printf("sheen, normal map vs tilted normals: worst %.2e of the peak; the tilt moves the image by %.2f\n", d, moved);
  EXPECT_LT(d, 2e-3);
  EXPECT_GT(moved, 0.05);
}

// A rung that draws neither says so, naming the object; the per-vertex iwasaki rungs need tables,
// so the one tried here is mdfrot.
TEST(ClothTextureWarnings, ARungThatIgnoresTheMapsSaysSo) {
  Scene scene = load_scene_preset("swatch", WEFT_SOURCE_ASSETS "/scenes");
  scene.objects[0].thread_maps[0] = scene.objects[0].thread_maps[1] = ThreadMap{one_colour(200, 100, 50), "warp", {}};
  scene.objects[0].normal_map = NormalMap{ThreadMap{one_colour(170, 100, 230), "normals", {}}, 1.0};
  gpu::EglContext ctx = gpu::EglContext::headless();
  const gpu::SceneRenderer mdfrot(scene, {fabric_of(scene)}, methods::method("mdfrot"), 16, nullptr);
  ASSERT_EQ(mdfrot.warnings().size(), 2u);
  EXPECT_NE(mdfrot.warnings()[0].find("without its texture"), std::string::npos) << mdfrot.warnings()[0];
  EXPECT_NE(mdfrot.warnings()[1].find("ignores the normal map of cloth object 'swatch'"), std::string::npos)
      << mdfrot.warnings()[1];
  const gpu::SceneRenderer sheen(scene, {fabric_of(scene)}, methods::method("sheen"), 16, nullptr);
  EXPECT_TRUE(sheen.warnings().empty());
}
