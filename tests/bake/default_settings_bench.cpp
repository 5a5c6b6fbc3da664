// How the default bake's settings were derived (label bench; never in CI): on the showroom
// scenes, the cheapest setting whose image error on the scene's views is within 0.5 points of
// the paper setting's (bake/scene_selection.h with paper_margin 0.005), at the paper's grid.
// Prints each search's table; WEFT_BENCH_SCENES="scene:fabric,..." narrows the cases and
// WEFT_BENCH_METHOD picks the method (default iwasaki, per pixel: the bench's paper row).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "bake/selection_bundle.h"
#include "runtime/paper_tangent_samples.h"
#include "lighting/env_map.h"
#include "lighting/sg_fit.h"

using namespace weft;

TEST(DefaultSettings, CheapestWithinHalfAPointOfThePaper) {
  std::string cases = "pillow:linen_plain,drape:polyester_satin_charmeuse";
  if (const char* c = std::getenv("WEFT_BENCH_SCENES")) cases = c;
  const char* method = std::getenv("WEFT_BENCH_METHOD");
  std::stringstream list(cases);
  std::string item;
  while (std::getline(list, item, ',')) {
    const auto colon = item.find(':');
    const std::string scene_name = item.substr(0, colon), fabric = item.substr(colon + 1);
    Scene scene = load_scene_named(scene_name, WEFT_SOURCE_ASSETS, fabric);
    std::map<std::string, Fabric> fabrics;
    std::map<std::string, std::string> texts;
    for (auto& o : scene.objects)
      if (o.material == Material::cloth) {
        o.fabric = fabric;
        std::ifstream in(fabric_file(fabric, WEFT_SOURCE_ASSETS "/fabrics"));
        std::ostringstream text;
        text << in.rdbuf();
        texts[fabric] = text.str();
        fabrics.emplace(fabric, parse_fabric(text.str(), fabric));
      }
    SgFitOptions fit;
    const SgLighting sgs = fit_sgs(
        load_env_map(env_map_file(scene.environment, WEFT_SOURCE_ASSETS "/envmaps"), NonFinitePolicy::clamp), fit);
    SceneSelectionOptions o;
    o.paper_margin = 0.005;
    o.cache = default_reference_cache();
    o.knobs.methods = {method ? method : "iwasaki"};
    // Around the paper's setting: its tangent samples (no other table bake), the cheaper values
    // of the knobs cut from its bake, and SDF 64 (one more visibility bake).
    o.knobs.tangent_samples = {std::max(paper_tangent_samples(fabrics.at(fabric))[0], 1)};
    o.knobs.svd_errors = {0.03, 0.02, 0.01};
    o.knobs.level_strides = {4, 2, 1};
    o.knobs.sdf_resolutions = {64, 128};
    o.knobs.pca_errors = {0.04, 0.02, 0.01};
    o.log = [](const std::string& line) { std::fprintf(stderr, "  select: %s\n", line.c_str()); };
    const SceneSelection s = select_scene_settings(scene, fabrics, texts, sgs, o);
    std::printf("== %s / %s\n%s", scene_name.c_str(), fabric.c_str(), selection_summary(s, o).c_str());
    ASSERT_TRUE(s.paper.has_value());
    EXPECT_LE(s.chosen.error, s.paper->error + 0.005);
  }
}
