#pragma once
// KHR_materials_variants in the glTF importer (gltf_scene.h): the file's variants, which material
// each primitive wears in each, and the colourways they make of the scene's cloth objects.
#include <set>
#include <string>
#include <vector>

#include "scene/gltf_materials.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace weft {

inline constexpr const char* kVariants = "KHR_materials_variants";

class GltfVariants {
public:
  // Reads the file's list of variants (none without the extension). Throws SceneError starting
  // with `origin` when the list is empty or a variant has no name.
  GltfVariants(const tinygltf::Model& model, std::string origin);

  // Records the materials primitive `p` (named `where` in messages) wears in each variant.
  void map(const tinygltf::Primitive& p, const std::string& where);
  // One colourway per variant: the look each cloth object wears in it. `object_names` holds the
  // scene object of each material slot, "" for a slot without one. A slot whose primitives wear
  // different materials in a variant, or one that is cloth in one look and not in another, is
  // refused.
  std::vector<Colourway> colourways(const std::vector<std::string>& object_names, const GltfMaterials& materials) const;

private:
  [[noreturn]] void fail(const std::string& what) const;

  const tinygltf::Model& m_;
  std::string origin_;
  std::vector<std::string> variants_;  // the variants' names, in order
  // Per variant, per material slot: the slots that slot's primitives wear in it.
  std::vector<std::vector<std::set<size_t>>> worn_;
};

}  // namespace weft
