#pragma once
// A glTF material with KHR_materials_sheen as cloth: which preset's weave its factors look like,
// and the colour its threads take. Rule and reasons: docs/design.md §1 ("glTF materials as cloth").
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace tinygltf {
struct Material;
}

namespace weft {

inline constexpr const char* kSheenExtension = "KHR_materials_sheen";
// The preset for cloth whose weave nothing states (a generic name such as "Fabric" without a
// sheen): the matte plain weave most upholstery is.
inline constexpr const char* kDefaultClothPreset = "linen_plain";

// The factors the rule reads, each in glTF's range [0, 1], with the spec's defaults.
struct SheenFactors {
  glm::dvec3 sheen_colour{0.0};  // sheenColorFactor: black turns the sheen layer off
  double sheen_roughness = 0.0;  // sheenRoughnessFactor
  glm::dvec3 base_colour{1.0};   // pbrMetallicRoughness.baseColorFactor's RGB
  double base_roughness = 1.0;   // pbrMetallicRoughness.roughnessFactor
};

// Whether the sheen layer is on: the spec turns it off when sheenColorFactor is zero.
bool sheen_is_on(const SheenFactors& f);

// The preset whose weave a material with a sheen layer that is on looks like most.
std::string sheen_preset(const SheenFactors& f);

// The product colour of cloth in `preset` chosen by sheen_preset: the base colour, or the sheen
// colour for a velvet whose sheen outshines a dark base.
glm::dvec3 sheen_thread_colour(const SheenFactors& f, const std::string& preset);

// Material `m`'s factors, none when it has no KHR_materials_sheen. A factor of the wrong type or
// not finite throws SceneError naming `where` (e.g. "materials[2] ('Sofa')") and the field; one
// outside [0, 1] is clamped, with a note in `notes`.
std::optional<SheenFactors> read_sheen_factors(const tinygltf::Material& m, const std::string& where,
                                               std::vector<std::string>& notes);

// The factors for the log: "sheen 0.9 at roughness 0.6, base roughness 0.7".
std::string describe_sheen(const SheenFactors& f);

}  // namespace weft
