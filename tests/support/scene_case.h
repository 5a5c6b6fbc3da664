#pragma once
// A bundled scene with every cloth object dressed in one fabric preset, as the bake search reads it:
// the scene, its fabric (parsed and as text) and the 10 SGs fitted to its own map.
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "lighting/env_map.h"
#include "lighting/sg_fit.h"
#include "scene/scene_file.h"

namespace weft::test {

struct SceneCase {
  Scene scene;
  std::map<std::string, Fabric> fabrics;
  std::map<std::string, std::string> texts;
  SgLighting sgs;
};

// Every cloth object of `scene` in the preset `fabric`; the preset by name, as the bake reads it.
inline std::map<std::string, Fabric> dress_cloth(Scene& scene, const std::string& fabric) {
  std::map<std::string, Fabric> fabrics;
  for (auto& o : scene.objects)
    if (o.material == Material::cloth) {
      o.fabric = fabric;
      fabrics.try_emplace(fabric, load_fabric_preset(fabric, WEFT_SOURCE_ASSETS "/fabrics"));
    }
  return fabrics;
}

inline SceneCase scene_in_fabric(const std::string& scene_name, const std::string& fabric) {
  SceneCase c;
  c.scene = load_scene_named(scene_name, WEFT_SOURCE_ASSETS, fabric);
  for (auto& o : c.scene.objects)
    if (o.material == Material::cloth) {
      o.fabric = fabric;
      std::ifstream in(fabric_file(fabric, WEFT_SOURCE_ASSETS "/fabrics"));
      std::ostringstream text;
      text << in.rdbuf();
      c.texts[fabric] = text.str();
      c.fabrics.emplace(fabric, parse_fabric(text.str(), fabric));
    }
  c.sgs = fit_sgs(
      load_env_map(env_map_file(c.scene.environment, WEFT_SOURCE_ASSETS "/envmaps"), NonFinitePolicy::clamp), {});
  return c;
}

}  // namespace weft::test
