// A scene's units do not change its frame: a product modelled in millimetres is a thousand times
// larger in numbers than the same product in metres, and the GPU's near and far planes must hold
// either. The swatch scaled by 1000 and by 1/1000 (its positions and its camera) must draw what the
// swatch draws, under the same directional SG light (shading has no length in it).
#include <gtest/gtest.h>

#include "core/fabric.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "gpu/scene_renderer.h"
#include "methods/registry.h"
#include "scene/scene_file.h"

using namespace weft;
using glm::dvec3;

namespace {

constexpr int kWidth = 48, kHeight = 36;

Image draw(const Scene& scene) {
  const Fabric fabric =
      object_base_fabric(scene.objects[0], load_fabric_preset(scene.objects[0].fabric, WEFT_SOURCE_ASSETS "/fabrics"));
  gpu::EglContext ctx = gpu::EglContext::headless();
  gpu::SceneRenderer renderer(scene, {fabric}, methods::method("sheen"), 16, nullptr);
  renderer.set_lighting({SphericalGaussian{glm::normalize(dvec3(0.3, -0.5, 0.8)), 30.0, dvec3(5.0)}});
  gpu::OffscreenTarget target(kWidth, kHeight);
  target.bind();
  renderer.draw(scene.camera, kWidth, kHeight);
  return gpu::read_linear_image(kWidth, kHeight);
}

Scene scaled(Scene s, double k) {
  for (auto& o : s.objects)
    for (auto& p : o.mesh.positions) p *= k;
  s.camera.position *= k;
  s.camera.target *= k;
  return s;
}

}  // namespace

TEST(SceneUnits, MillimetresAndKilometresDrawWhatMetresDraw) {
  const Scene metres = load_scene_preset("swatch", WEFT_SOURCE_ASSETS "/scenes");
  const Image want = draw(metres);
  double top = 0.0;
  size_t lit = 0;
  for (const auto& p : want.pixels) top = std::max(top, p.g), lit += p.g > 0.0;
  ASSERT_GT(lit, want.pixels.size() / 10);  // the swatch is in the frame
  for (const double k : {1000.0, 0.001}) {
    const Image got = draw(scaled(metres, k));
    double worst = 0.0;
    for (size_t i = 0; i < got.pixels.size(); ++i)
      worst = std::max(worst, glm::length(got.pixels[i] - want.pixels[i]));
    EXPECT_LT(worst, 1e-3 * top) << "scaled by " << k;
  }
}
