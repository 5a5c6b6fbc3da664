#pragma once
// Scene files: a scene JSON (assets/scenes/README.md) or a glTF, read into a Scene. Only the
// offline tools read them (the kiosk reads the scene its bundle holds), so this and the glTF
// importer with its Draco and meshoptimizer decoders live in weft_scene_files, which the kiosk
// does not link.
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace weft {

// What a scene that imports a glTF needs besides its own files (render/scene/gltf_scene.h).
struct SceneLoadOptions {
  std::filesystem::path fabrics_dir;  // preset fabrics: a glTF material named like one is cloth
  std::string fallback_fabric;        // a glTF naming no cloth: every material is cloth with this
};

// Parses a scene description; meshes are generated (and repaired) here, or imported from the
// glTF file its "gltf" field names. `base_dir` resolves data files (the teapot's patches, the
// glTF, fabric files). `origin` names the text in errors.
Scene parse_scene(const std::string& json_text, const std::string& origin, const std::filesystem::path& base_dir,
                  const SceneLoadOptions& options = {});
// A .json scene file, or a .gltf/.glb file (by its extension).
Scene load_scene(const std::filesystem::path& file, const SceneLoadOptions& options = {});
// `<dir>/<name>.json`.
Scene load_scene_preset(const std::string& name, const std::filesystem::path& dir, const SceneLoadOptions& options = {});
std::vector<std::string> list_scene_presets(const std::filesystem::path& dir);

// True when `name` is a file path rather than a preset name: it has a directory part or ends
// in .json, .gltf or .glb.
bool names_scene_file(const std::string& name);
// A scene as the command line names it: a file path (names_scene_file) or a preset in
// `<assets>/scenes`; glTF material presets come from `<assets>/fabrics`.
Scene load_scene_named(const std::string& name, const std::filesystem::path& assets,
                       const std::string& fallback_fabric = "");

}  // namespace weft
