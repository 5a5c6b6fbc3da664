#pragma once
// A scene object's own fields (SceneObject less its mesh) in JSON: the one place they are read,
// checked and written. A scene file's objects, the bundle's scene section and a glTF material's
// extras.weft spell them with the same keys; each reader takes the fields its source holds.
//
// Every reader takes the JSON object that holds the field and `where`, the object's name in
// messages ("room.json: objects[2]", "materials[0] ('Sofa').extras.weft"). A bad value throws
// SceneError "<where>.<key>: <the problem>, got <the value>"; a missing required field,
// "<where>: missing field '<key>'".
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scene/scene.h"

namespace weft {

// "cloth" or "lambertian": how files and reports spell a material.
const char* material_name(Material material);

// Required: a string.
std::string read_object_name(const nlohmann::json& object, const std::string& where);
// Required: "cloth" or "lambertian".
Material read_material(const nlohmann::json& object, const std::string& where);
// Cloth, required: a preset name or a fabric file, not empty.
std::string read_fabric(const nlohmann::json& object, const std::string& where);
// Cloth, optional: τ in (0, kMaxOpticalThickness]; absent, 0 (the fabric's own).
double read_optical_thickness(const nlohmann::json& object, const std::string& where);
// Cloth, optional: [along u, along v], each in (0, kMaxWeaveRepeatsPerUv]; absent, (0, 0).
glm::dvec2 read_weave_repeats_per_uv(const nlohmann::json& object, const std::string& where);
// Cloth, optional: the product's colour (product_colour's rules); absent, none.
std::optional<glm::dvec3> read_colour(const nlohmann::json& object, const std::string& where);
// Cloth, optional: "display_name" or "composition", a label text (fabric_text_problem's rules);
// absent, "".
std::string read_label_text(const nlohmann::json& object, const char* key, const std::string& where);
// Lambertian, required: [r, g, b], each in [0, 1].
glm::dvec3 read_albedo(const nlohmann::json& object, const std::string& where);

// A colour value itself (a colourway's look holds one too): [r, g, b] under product_colour's
// rules, messages naming `where`.
glm::dvec3 colour_from_json(const nlohmann::json& value, const std::string& where);
// A map's transform within its JSON object: "offset" and "scale" ([u, v]) and "rotation"
// (radians), each optional with TextureTransform's defaults, checked by texture_transform_problem.
// Other keys are the caller's.
TextureTransform read_texture_transform(const nlohmann::json& map, const std::string& where);
// A normal map's scale, `value` named `where` itself ("…normal_map.normal_scale",
// "…normalTexture.scale"): a finite number within ±10^6.
double normal_scale_from_json(const nlohmann::json& value, const std::string& where);

// An image as the bundle's scene section lists it: what a map's "texture" index refers to.
struct SectionTexture {
  std::shared_ptr<const TextureImage> image;
  std::string name;
};

// The whole object as the bundle's scene section holds it (BUNDLE_FORMAT.md): name, material,
// then cloth: fabric, optical_thickness, weave_repeats_per_uv, colour, display_name,
// composition, thread_maps ([warp, weft], each null or {"texture", "offset", "scale",
// "rotation"}) and normal_map (the same plus "normal_scale"), textures by index into `textures`;
// lambertian: albedo. `where` names the object until its name is read ("objects[3]"), then
// "<where> ('<name>')". The mesh is left empty.
SceneObject read_scene_object(const nlohmann::json& object, const std::string& where,
                              const std::vector<SectionTexture>& textures);
// The same fields written: what read_scene_object reads back. `texture_index` gives a map's
// image's index in the section's texture list. Fields at their "absent" value are left out.
nlohmann::json write_scene_object(const SceneObject& o, const std::function<std::size_t(const ThreadMap&)>& texture_index);

}  // namespace weft
