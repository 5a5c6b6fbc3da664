#pragma once
// The fabrics a scene's cloth wears, loaded as the offline commands take them: each by the name
// its objects give (a preset in `dir`, or a fabric file's path), and named by it, as a bundle
// names its fabrics, so that tables baked for it are found under the same name.
#include <filesystem>
#include <map>
#include <string>

#include "core/fabric.h"
#include "scene/scene.h"

namespace weft {

// Throws FabricError naming the fabric that does not load.
std::map<std::string, Fabric> load_scene_fabrics(const Scene& scene, const std::filesystem::path& dir);

}  // namespace weft
