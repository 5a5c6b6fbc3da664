// The bench's thin-occluder stress scene (`teapot`) keeps what it is for: under the
// sharp sun of the 10-SG fit to its map, rays from the cloth the camera sees toward that sun are
// blocked by the spout alone for some pixels and by the handle alone for others (shadows of
// their own, not hidden in the body's), and most of the cloth is sunlit. Checked by Embree rays against the scene itself, so an edit to the scene file (the
// camera, the teapot's rotation, the map) cannot silently lose the shadows the bench measures.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "lighting/env_map.h"
#include "lighting/sg_fit.h"
#include "reference/ray_scene.h"
#include "scene/scene_file.h"

using namespace weft;
using glm::dvec3;

static const std::filesystem::path kAssets = WEFT_SOURCE_ASSETS;

TEST(TeapotScene, SpoutAndHandleShadowTheClothInView) {
  const Scene scene = load_scene_preset("teapot", kAssets / "scenes");
  size_t teapot = scene.objects.size();
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].name == "teapot") teapot = i;
  ASSERT_LT(teapot, scene.objects.size());

  // The sun: the SG of highest peak radiance fitted to the scene's own map, as the bench fits it.
  const EnvMap map = load_env_map(kAssets / "envmaps" / (scene.environment + ".exr"), NonFinitePolicy::clamp);
  const SgLighting sgs = fit_sgs(map, SgFitOptions{});
  const SphericalGaussian* sun = &sgs.front();
  for (const auto& g : sgs)
    if (g.amplitude.r + g.amplitude.g + g.amplitude.b > sun->amplitude.r + sun->amplitude.g + sun->amplitude.b) sun = &g;
  // Crisp shadows need a narrow lobe (λ = 100: ~8° wide) well above the horizon.
  EXPECT_GT(sun->sharpness, 100.0);
  ASSERT_GT(sun->axis.z, 0.3);
  const dvec3 to_sun = glm::normalize(sun->axis);

  // The teapot's own frame from the scene file: Newell's pot has its spout along +x, its handle
  // along −x; its body is at most 2.0 units from the axis, so a point further out is spout or handle.
  std::ifstream in(kAssets / "scenes" / "teapot.json");
  const auto file = nlohmann::json::parse(in);
  double scale = 0, rotate = 0;
  dvec3 shift(0.0);
  for (const auto& o : file["objects"])
    if (o["name"] == "teapot") {
      scale = o["mesh"]["scale"], rotate = o["mesh"].value("rotate_z_deg", 0.0);
      shift = dvec3(o["mesh"]["translate"][0], o["mesh"]["translate"][1], o["mesh"]["translate"][2]);
    }
  ASSERT_GT(scale, 0.0);
  const double a = rotate * std::numbers::pi / 180.0;
  const dvec3 spout_dir(std::cos(a), std::sin(a), 0.0);

  const RayScene rays(scene);
  const int w = 160, h = 120;
  int cloth = 0, sunlit = 0, by_spout = 0, by_handle = 0, by_body = 0, by_other = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const dvec3 dir = camera_ray(scene.camera, w, h, x + 0.5, y + 0.5);
      const auto hit = rays.intersect(scene.camera.position, dir);
      if (!hit || scene.objects[hit->object].material != Material::cloth) continue;
      ++cloth;
      const SurfacePoint s = rays.surface(*hit);
      const dvec3 ng = glm::dot(s.geometric_normal, dir) > 0.0 ? -s.geometric_normal : s.geometric_normal;
      // Every surface the sun ray crosses, classified: a shadow counts as the spout's (handle's)
      // only where nothing else blocks that ray, i.e. where the spout alone casts it.
      enum Part { none = 0, spout = 1, handle = 2, body = 4, other = 8 };
      int parts = none;
      dvec3 origin = s.position + ng * rays.ray_epsilon();
      for (int crossings = 0; crossings < 32; ++crossings) {
        const auto blocker = rays.intersect(origin, to_sun);
        if (!blocker) break;
        const dvec3 q = rays.surface(*blocker).position;
        origin = q + to_sun * rays.ray_epsilon();
        if (blocker->object != teapot) {
          parts |= other;  // the cloth's own folds
          continue;
        }
        const dvec3 p = (q - shift) / scale;  // pot units, rotated
        if (std::hypot(p.x, p.y) <= 2.02) parts |= body;
        else parts |= glm::dot(dvec3(p.x, p.y, 0.0), spout_dir) > 0 ? spout : handle;
      }
      if (parts == none) ++sunlit;
      else if (parts == spout) ++by_spout;
      else if (parts == handle) ++by_handle;
      else if (parts & body) ++by_body;
      else ++by_other;
    }
  // Most of the frame is cloth, most of it sunlit; the spout and the handle each shadow a patch
  // of it (at 160x120, 40 pixels are 0.2 % of the frame: a shadow, not a grazing speck).
  EXPECT_GT(cloth, w * h / 2);
  EXPECT_GT(sunlit, cloth / 2);
  EXPECT_GE(by_spout, 40) << "the spout's shadow is out of view";
  EXPECT_GE(by_handle, 40) << "the handle's shadow is out of view";
  EXPECT_GT(by_body, 0);
  RecordProperty("cloth_pixels", cloth);
  std::cout << "cloth " << cloth << ", sunlit " << sunlit << ", shadowed by spout " << by_spout << ", handle "
            << by_handle << ", body " << by_body << ", folds or several parts " << by_other << "\n";
}
