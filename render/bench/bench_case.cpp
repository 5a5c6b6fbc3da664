#include "bench/bench_case.h"

#include <filesystem>

#include "bench/number_text.h"
#include "lighting/env_map.h"
#include "lighting/env_spec.h"
#include "lighting/sg_fit.h"
#include "scene/scene_fabrics.h"
#include "scene/scene_file.h"

namespace weft::bench {

Case make_case(const BenchOptions& a, const std::string& scene_name, const std::string& fabric_arg,
               const std::string& env_arg) {
  Case c;
  c.scene_name = scene_name;
  try {
    c.scene = load_scene_named(scene_name, a.assets, fabric_arg == "scene" ? "" : fabric_arg);
  } catch (const SceneError& e) {
    throw InvalidOption(e.what());
  }
  if (fabric_arg != "scene")
    for (auto& o : c.scene.cloth_objects()) o.fabric = fabric_arg;
  try {
    c.fabrics = load_scene_fabrics(c.scene, a.assets / "fabrics");
  } catch (const FabricError& e) {
    throw InvalidOption(std::string("--fabrics: ") + e.what());
  }
  if (c.fabrics.empty()) throw InvalidOption("--scenes: " + scene_name + " has no cloth");
  c.fabric_label = fabric_arg == "scene" ? c.fabrics.begin()->first : fabric_arg;
  c.env = env_arg == "scene" ? c.scene.environment : env_arg;
  EnvMap map;
  try {
    const auto env_file = env_spec_file(c.env, a.assets / "envmaps");
    if (!env_file.empty() && !std::filesystem::exists(env_file))
      throw InvalidOption("--maps: no environment map " + env_file.string());
    map = load_env(c.env, a.assets / "envmaps", NonFinitePolicy::clamp, nullptr);
  } catch (const EnvSpecError& e) {
    throw InvalidOption(std::string("--maps: ") + e.what());
  }
  SgFitOptions fit;
  fit.count = a.sg_count;
  c.sgs = fit_sgs(map, fit);
  // Paths name their file's stem in tags (which become file names).
  auto label = [](const std::string& name) {
    const std::filesystem::path p(name);
    return p.has_parent_path() || p.has_extension() ? p.stem().string() : name;
  };
  c.tag = label(scene_name) + "_" + label(c.fabric_label) + "_" + env_spec_label(c.env);
  if (scene_name == kThinOccluderScene)
    c.shadow = std::make_shared<ShadowMask>(sun_shadow_mask(c.scene, c.sgs, a.width, a.height));
  return c;
}

std::string thin_occluder_text(const Case& c) {
  const auto& sun = c.shadow->sun;
  return "`" + c.env + "` (its brightest SG: axis (" + fmt(sun.axis.x, 2) + ", " + fmt(sun.axis.y, 2) + ", " +
         fmt(sun.axis.z, 2) + "), λ = " + fmt(sun.sharpness) + "; on " + c.fabric_label + ", " +
         std::to_string(c.shadow->shadow_pixels) + " cloth pixels in its shadow, " +
         std::to_string(c.shadow->band_pixels) + " beside it)";
}

}  // namespace weft::bench
