#include "bake/writers/bundle_fabrics.h"

#include <fstream>
#include <sstream>

#include "core/fabric.h"

namespace weft {

namespace {

std::string preset_text(const std::filesystem::path& dir, const std::string& name) {
  const std::string path = fabric_file(name, dir).string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw BundleFabricError("fabric: cannot open '" + path + "'");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::map<std::string, std::string> bundle_fabric_texts(const Scene& scene, const std::filesystem::path& dir,
                                                       bool only_scene) {
  std::map<std::string, std::string> texts;
  for (const std::string& name : worn_fabrics(scene)) {
    try {
      load_fabric_named(name, dir);  // validates; throws naming the known presets or the file's problem
    } catch (const std::exception& e) {
      throw BundleFabricError(std::string("--fabric: ") + e.what());
    }
    texts.emplace(name, preset_text(dir, name));
  }
  if (!only_scene)
    for (const auto& name : list_fabric_presets(dir))
      if (!texts.count(name)) texts.emplace(name, preset_text(dir, name));
  return texts;
}

std::map<std::string, Fabric> cloth_fabrics(const Scene& scene, const std::map<std::string, std::string>& fabric_texts) {
  std::map<std::string, Fabric> fabrics;
  for (const std::string& name : worn_fabrics(scene)) fabrics.emplace(name, parse_fabric(fabric_texts.at(name), name));
  return fabrics;
}

}  // namespace weft
