#pragma once
// The scene part of a bundle (BUNDLE_FORMAT.md, "Scene bundle sections"): meshes, materials,
// fabric parameters, camera and default SGs, written by `weft bake` (render/bake/writers/scene_bundle_writer.h)
// and read back here for `weft run`.
// Tables baked by other stages (T, SDF/PCA, κ, T_l) go beside these under their own names.
#include <filesystem>
#include <map>
#include <string>

#include "bundle/bundle_reader.h"
#include "core/fabric.h"
#include "core/spherical_gaussian.h"
#include "scene/scene.h"

namespace weft {

// Section names (one source of truth; BUNDLE_FORMAT.md lists them).
namespace scene_section {
inline constexpr const char* kScene = "scene";            // json: name, camera, objects, environment
inline constexpr const char* kSgs = "lighting/sgs";       // json: weft-sg-set
inline constexpr const char* kFabrics = "fabrics";         // json: {preset: fabric file object, ...}
std::string mesh(size_t object, const char* attribute);   // "mesh/<i>/<attribute>"
std::string texture(size_t index);                        // "texture/<n>": u8, a PNG
}  // namespace scene_section

struct SceneBundle {
  Scene scene;
  std::map<std::string, Fabric> fabrics;       // parsed copies: the knobs edit these
  std::map<std::string, std::string> fabric_json;
  SgLighting sgs;
};

// Reads the scene sections of a verified bundle. Throws bundle::BundleError naming the section
// when one is missing, has the wrong type or shape, or holds invalid data (bad JSON, a fabric
// that does not parse, indices out of range, non-finite values).
SceneBundle read_scene_bundle(const bundle::BundleReader& reader);

// Opens, verifies and reads a bundle file.
SceneBundle load_scene_bundle(const std::filesystem::path& file);

}  // namespace weft
