// The reference's resolved weave, averaged down, against its fabric-level render of the same
// swatch: one model at every distance. A camera square above the swatch maps the weave's repeat
// onto exactly 8×8 pixels (80×80 rays), so each block of the resolved image averages whole repeats; the
// block means must match the fabric-level image's, per preset, within 2 %.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/fabric.h"
#include "reference/scene_render.h"
#include "scene/scene_file.h"
#include "scene/weave_scale.h"
#include "support/block_means.h"

using namespace weft;
using glm::dvec3;

static const std::filesystem::path kAssets = WEFT_SOURCE_ASSETS;

namespace {
// A 1 m swatch seen from 1 m straight above with a 0.1 m wide view: 16 px over 2 repeats.
Scene top_down_swatch(const std::string& fabric) {
  const std::string json = R"({"name": "top", "environment": "studio",
    "camera": {"position": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": )" +
                           std::to_string(2.0 * std::atan(0.05) * 180.0 / M_PI) + R"(},
    "objects": [{"name": "swatch", "material": "cloth", "fabric": ")" + fabric + R"(",
                 "weave_repeats_per_uv": [20, 20], "mesh": {"generator": "swatch", "size": 1.0, "resolution": 4}}]})";
  return parse_scene(json, "top.json", kAssets / "scenes");
}

ReferenceLighting three_lights() {
  ReferenceLighting l;
  l.samples = [](int) {
    return std::vector<DirectionalSample>{{glm::normalize(dvec3(-0.4, -0.5, 0.75)), {2.0, 1.9, 1.8}},
                                          {glm::normalize(dvec3(0.6, 0.1, 0.5)), {0.6, 0.7, 0.9}},
                                          {glm::normalize(dvec3(0.05, 0.7, 0.3)), {0.5, 0.5, 0.4}}};
  };
  l.description = "three directional lights";
  return l;
}
}  // namespace

TEST(ResolvedWeaveReference, AveragedOverRepeatsEqualsFabricLevelForEveryPreset) {
  constexpr int kSize = 16, kBlock = 8;
  for (const std::string& name : list_fabric_presets(kAssets / "fabrics")) {
    const Fabric f = load_fabric_preset(name, kAssets / "fabrics");
    const Scene scene = top_down_swatch(name);
    ASSERT_DOUBLE_EQ(weave_tiles_per_uv(scene.objects[0], f).x, 20.0);  // 5 cm repeats over 8 px of 6.25 mm
    ReferenceRenderOptions opt;
    opt.width = opt.height = kSize;
    opt.tangent_samples = 64;
    opt.check_convergence = false;
    opt.supersample = 10;  // 80 rays across a repeat: whole rays per row of 2, 4 or 5 and per satin's weft float
    const ReferenceRenderer fabric_level(scene, {{name, f}}, three_lights(), opt);
    opt.resolved_weave = true;
    const ReferenceRenderer resolved(scene, {{name, f}}, three_lights(), opt);
    const Image a = fabric_level.render().image, b = resolved.render().image;
    const test::BlockComparison c = test::compare_blocks(a, b, kBlock);
    std::cout << name << ": repeats averaged against fabric level " << c.block_means << "\n";
    EXPECT_LT(c.block_means, 0.02) << name;
    // Resolved is not the average in disguise: single pixels differ from it by far more.
    EXPECT_GT(c.pixels, 0.3) << name;
  }
}

// UVs collapsed to one point leave the threads no place: the resolved reference is the fabric
// level there, pixel for pixel (as the weave layer keeps the method's shading).
TEST(ResolvedWeaveReference, CollapsedUvsKeepTheFabricLevel) {
  const std::string name = "polyester_satin_charmeuse";
  const Fabric f = load_fabric_preset(name, kAssets / "fabrics");
  Scene scene = top_down_swatch(name);
  for (auto& uv : scene.objects[0].mesh.uvs) uv = glm::dvec2(0.37, 0.61);
  ReferenceRenderOptions opt;
  opt.width = opt.height = 8;
  opt.tangent_samples = 16;
  opt.check_convergence = false;
  opt.supersample = 2;
  const ReferenceRenderer fabric_level(scene, {{name, f}}, three_lights(), opt);
  opt.resolved_weave = true;
  const ReferenceRenderer resolved(scene, {{name, f}}, three_lights(), opt);
  const Image a = fabric_level.render().image, b = resolved.render().image;
  double worst = 0.0, level = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    worst = std::max(worst, glm::length(a.pixels[i] - b.pixels[i]));
    level = std::max(level, glm::length(a.pixels[i]));
  }
  EXPECT_GT(level, 0.0);
  EXPECT_LE(worst, 1e-12 * level);
}
