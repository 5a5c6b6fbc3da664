#include "scene/scene_fabrics.h"

namespace weft {

std::map<std::string, Fabric> load_scene_fabrics(const Scene& scene, const std::filesystem::path& dir) {
  std::map<std::string, Fabric> fabrics;
  for (const SceneObject& o : scene.cloth_objects()) {
    if (fabrics.count(o.fabric)) continue;
    Fabric f = load_fabric_named(o.fabric, dir);
    f.name = o.fabric;  // a file's own name may differ from its path
    fabrics.emplace(o.fabric, std::move(f));
  }
  return fabrics;
}

}  // namespace weft
