#pragma once
// The glTF importer's materials (gltf_scene.h): which are cloth and in which fabric (an override,
// extras.weft.fabric, a preset's name, the name's words or KHR_materials_sheen; docs/design.md §1,
// "glTF materials as cloth"), a cloth's extras.weft fields (scene/object_schema.h), product
// colour, textures and normal map, and a Lambertian's albedo.
//
// Materials go by slot: index + 1, slot 0 being glTF's default material (primitives without one).
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scene/gltf_scene.h"

namespace tinygltf {
class Model;
}

namespace weft {

inline constexpr const char* kTextureTransform = "KHR_texture_transform";

// A material slot's name for messages: "materials[2] ('Sofa')", "(default)" for slot 0.
std::string material_label(const tinygltf::Model& model, size_t slot);

class GltfMaterials {
public:
  // Resolves every material of `model`. Throws SceneError starting with `origin` for a material
  // it cannot use; adds what it inferred (cloth by name or sheen) to `notes`, which must outlive
  // this.
  GltfMaterials(const tinygltf::Model& model, std::string origin, std::filesystem::path base_dir,
                const GltfImportOptions& options, std::vector<std::string>& notes);

  size_t slots() const { return slots_.size(); }
  // The slot's fabric (a preset name or a fabric file), "" when it is Lambertian.
  const std::string& fabric(size_t slot) const { return slots_[slot].fabric; }
  bool cloth(size_t slot) const { return !slots_[slot].fabric.empty(); }
  // A cloth slot's product colour: its baseColorFactor's RGB when the file gives one (absent,
  // glTF's default white is no colour of the product's: the fabric's own stays); for a material
  // with a sheen made cloth by its name or sheen, the colour sheen_thread_colour gives. None for
  // slot 0.
  std::optional<glm::dvec3> cloth_colour(size_t slot) const;
  // Gives `o` (its mesh already merged) the slot's material and fields; a cloth's textures are
  // decoded here, each image once.
  void dress(SceneObject& o, size_t slot);

private:
  [[noreturn]] void fail(const std::string& what) const;
  void resolve(size_t index);  // material `index` into slot index + 1
  // A material's fabric from extras.weft.fabric: a preset name or a file relative to the glTF.
  std::string named_fabric(const nlohmann::json& weft, const std::string& where) const;
  // What a material that neither an override, its extras nor a preset's name makes cloth is taken
  // as from its name and its KHR_materials_sheen: a preset name, or "" for Lambertian; notes why.
  std::string inferred_fabric(size_t index);
  // Material `index`'s textures (baseColorTexture on both threads, extras.weft.weft_texture the
  // weft's own); none when it has no baseColorTexture.
  std::array<std::optional<ThreadMap>, 2> cloth_maps(size_t index);
  // Material `index`'s normalTexture with its scale, none when it has none.
  std::optional<NormalMap> cloth_normal_map(size_t index);
  // `transform`: the reference's KHR_texture_transform as JSON, null when it has none.
  ThreadMap thread_map(const nlohmann::json* transform, int texture, int texcoord, const std::string& where);
  std::shared_ptr<const TextureImage> image(int index, const std::string& where);

  struct Slot {
    std::string fabric;  // "" = Lambertian
    double optical_thickness = 0.0;
    glm::dvec2 weave_repeats_per_uv{0.0};
    std::string display_name, composition;
    // The thread colour of a material with a sheen made cloth by its name or sheen
    // (sheen_thread_colour), none otherwise.
    std::optional<glm::dvec3> sheen_colour;
  };

  const tinygltf::Model& m_;
  std::string origin_;
  std::filesystem::path base_dir_;
  const GltfImportOptions& options_;
  std::vector<std::string>& notes_;
  std::vector<Slot> slots_;
  std::map<int, std::shared_ptr<const TextureImage>> images_;  // decoded, by image index
};

}  // namespace weft
