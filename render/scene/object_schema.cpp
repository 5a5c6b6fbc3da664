#include "scene/object_schema.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/fabric.h"
#include "scene/thread_maps.h"

namespace weft {

namespace {

using nlohmann::json;

constexpr const char* kName = "name";
constexpr const char* kMaterial = "material";
constexpr const char* kFabric = "fabric";
constexpr const char* kOpticalThickness = "optical_thickness";
constexpr const char* kWeaveRepeatsPerUv = "weave_repeats_per_uv";
constexpr const char* kColour = "colour";
constexpr const char* kDisplayName = "display_name";
constexpr const char* kComposition = "composition";
constexpr const char* kAlbedo = "albedo";
constexpr const char* kThreadMaps = "thread_maps";
constexpr const char* kNormalMap = "normal_map";
constexpr const char* kTexture = "texture";
constexpr const char* kNormalScale = "normal_scale";
constexpr double kMaxNormalScale = 1e6;

// The field `key` of `object`, or null when absent.
const json* optional_field(const json& object, const char* key, const std::string& where) {
  if (!object.is_object()) throw SceneError(where + ": expected an object");
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

const json& required_field(const json& object, const char* key, const std::string& where) {
  const json* v = optional_field(object, key, where);
  if (!v) throw SceneError(where + ": missing field '" + key + "'");
  return *v;
}

[[noreturn]] void refuse(const std::string& where, const char* key, const std::string& problem, const json& value) {
  throw SceneError(where + "." + key + ": " + problem + ", got " + value.dump());
}

std::optional<double> finite_number(const json& v) {
  if (!v.is_number()) return std::nullopt;
  const double x = v.get<double>();
  return std::isfinite(x) ? std::optional<double>(x) : std::nullopt;
}

glm::dvec2 number_pair(const json& object, const char* key, glm::dvec2 fallback, const std::string& where) {
  const json* v = optional_field(object, key, where);
  if (!v) return fallback;
  if (!v->is_array() || v->size() != 2 || !(*v)[0].is_number() || !(*v)[1].is_number())
    refuse(where, key, "expected [u, v]", *v);
  return {(*v)[0].get<double>(), (*v)[1].get<double>()};
}

json pair_json(glm::dvec2 v) { return json::array({v.x, v.y}); }
json vec3_json(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

// A map of the bundle's scene section: its image by index, its transform.
ThreadMap read_section_map(const json& map, const std::string& where, const std::vector<SectionTexture>& textures) {
  const json& index = required_field(map, kTexture, where);
  if (!index.is_number_integer() || index.get<long long>() < 0 || size_t(index.get<long long>()) >= textures.size())
    refuse(where, kTexture, "not among the " + std::to_string(textures.size()) + " textures", index);
  const SectionTexture& t = textures[size_t(index.get<long long>())];
  ThreadMap m;
  m.image = t.image;
  m.name = t.name;
  m.transform = read_texture_transform(map, where);
  return m;
}

json section_map_json(const ThreadMap& m, size_t texture) {
  const TextureTransform& t = m.transform;
  return {{kTexture, texture}, {"offset", pair_json(t.offset)}, {"scale", pair_json(t.scale)}, {"rotation", t.rotation}};
}

}  // namespace

const char* material_name(Material material) { return material == Material::cloth ? "cloth" : "lambertian"; }

std::string read_object_name(const json& object, const std::string& where) {
  const json& v = required_field(object, kName, where);
  if (!v.is_string()) refuse(where, kName, "expected a string", v);
  return v.get<std::string>();
}

Material read_material(const json& object, const std::string& where) {
  const json& v = required_field(object, kMaterial, where);
  if (!v.is_string()) refuse(where, kMaterial, "expected a string", v);
  const std::string name = v.get<std::string>();
  if (name == material_name(Material::cloth)) return Material::cloth;
  if (name == material_name(Material::lambertian)) return Material::lambertian;
  throw SceneError(where + "." + kMaterial + ": '" + name + "' is neither 'cloth' nor 'lambertian'");
}

std::string read_fabric(const json& object, const std::string& where) {
  const json& v = required_field(object, kFabric, where);
  if (!v.is_string() || v.get<std::string>().empty()) refuse(where, kFabric, "expected a preset name or a fabric file", v);
  return v.get<std::string>();
}

double read_optical_thickness(const json& object, const std::string& where) {
  const json* v = optional_field(object, kOpticalThickness, where);
  if (!v) return 0.0;
  const std::optional<double> tau = finite_number(*v);
  if (!tau || !(*tau > 0.0 && *tau <= kMaxOpticalThickness))
    refuse(where, kOpticalThickness, "expected a number in (0, " + std::to_string(int(kMaxOpticalThickness)) + "]", *v);
  return *tau;
}

glm::dvec2 read_weave_repeats_per_uv(const json& object, const std::string& where) {
  const json* v = optional_field(object, kWeaveRepeatsPerUv, where);
  if (!v) return glm::dvec2(0.0);
  const auto repeats = [&](size_t k) {
    const std::optional<double> x = v->is_array() && v->size() == 2 ? finite_number((*v)[k]) : std::nullopt;
    return x && *x > 0.0 && *x <= kMaxWeaveRepeatsPerUv ? *x : -1.0;
  };
  const glm::dvec2 r{repeats(0), repeats(1)};
  if (r.x < 0.0 || r.y < 0.0)
    refuse(where, kWeaveRepeatsPerUv,
           "expected [along u, along v], two numbers in (0, " + std::to_string(int(kMaxWeaveRepeatsPerUv)) + "]", *v);
  return r;
}

std::optional<glm::dvec3> read_colour(const json& object, const std::string& where) {
  const json* v = optional_field(object, kColour, where);
  if (!v) return std::nullopt;
  return colour_from_json(*v, where + "." + kColour);
}

std::string read_label_text(const json& object, const char* key, const std::string& where) {
  const json* v = optional_field(object, key, where);
  if (!v) return "";
  if (!v->is_string()) refuse(where, key, "expected a string", *v);
  const std::string text = v->get<std::string>();
  if (const std::string why = fabric_text_problem(text); !why.empty()) throw SceneError(where + "." + key + ": " + why);
  return text;
}

glm::dvec3 read_albedo(const json& object, const std::string& where) {
  const json& v = required_field(object, kAlbedo, where);
  glm::dvec3 albedo(-1.0);
  if (v.is_array() && v.size() == 3)
    for (int c = 0; c < 3; ++c)
      if (const std::optional<double> x = finite_number(v[size_t(c)]); x && *x >= 0.0 && *x <= 1.0) albedo[c] = *x;
  if (albedo.r < 0.0 || albedo.g < 0.0 || albedo.b < 0.0)
    refuse(where, kAlbedo, "expected [r, g, b], three numbers in [0, 1]", v);
  return albedo;
}

glm::dvec3 colour_from_json(const json& value, const std::string& where) {
  std::vector<double> rgb;
  if (value.is_array())
    for (const json& x : value) {
      if (!x.is_number()) break;
      rgb.push_back(x.get<double>());
    }
  if (!value.is_array() || rgb.size() != value.size())
    throw SceneError(where + ": expected a colour [r, g, b], got " + value.dump());
  return product_colour(rgb, where);
}

TextureTransform read_texture_transform(const json& map, const std::string& where) {
  TextureTransform t;
  t.offset = number_pair(map, "offset", t.offset, where);
  t.scale = number_pair(map, "scale", t.scale, where);
  if (const json* r = optional_field(map, "rotation", where)) {
    if (!r->is_number()) refuse(where, "rotation", "expected a number (radians)", *r);
    t.rotation = r->get<double>();
  }
  if (const std::string why = texture_transform_problem(t); !why.empty()) throw SceneError(where + ": " + why);
  return t;
}

double normal_scale_from_json(const json& value, const std::string& where) {
  const std::optional<double> s = finite_number(value);
  if (!s || std::abs(*s) > kMaxNormalScale)
    throw SceneError(where + ": expected a finite number within ±10^6, got " + value.dump());
  return *s;
}

SceneObject read_scene_object(const json& object, const std::string& where, const std::vector<SectionTexture>& textures) {
  SceneObject o;
  o.name = read_object_name(object, where);
  const std::string at = where + " ('" + o.name + "')";
  o.material = read_material(object, at);
  if (!o.is_cloth()) {
    o.albedo = read_albedo(object, at);
    return o;
  }
  o.fabric = read_fabric(object, at);
  o.optical_thickness = read_optical_thickness(object, at);
  o.weave_repeats_per_uv = read_weave_repeats_per_uv(object, at);
  o.colour = read_colour(object, at);
  o.display_name = read_label_text(object, kDisplayName, at);
  o.composition = read_label_text(object, kComposition, at);
  if (const json* maps = optional_field(object, kThreadMaps, at)) {
    const std::string w = at + "." + kThreadMaps;
    if (!maps->is_array() || maps->size() != 2) throw SceneError(w + ": expected [warp, weft], got " + maps->dump());
    for (size_t t = 0; t < 2; ++t)
      if (!(*maps)[t].is_null()) o.thread_maps[t] = read_section_map((*maps)[t], w + "[" + std::to_string(t) + "]", textures);
  }
  if (const json* map = optional_field(object, kNormalMap, at)) {
    const std::string w = at + "." + kNormalMap;
    NormalMap n;
    n.map = read_section_map(*map, w, textures);
    n.scale = normal_scale_from_json(required_field(*map, kNormalScale, w), w + "." + kNormalScale);
    o.normal_map = n;
  }
  return o;
}

json write_scene_object(const SceneObject& o, const std::function<size_t(const ThreadMap&)>& texture_index) {
  json j{{kName, o.name}, {kMaterial, material_name(o.material)}};
  if (!o.is_cloth()) {
    j[kAlbedo] = vec3_json(o.albedo);
    return j;
  }
  j[kFabric] = o.fabric;
  if (o.optical_thickness > 0.0) j[kOpticalThickness] = o.optical_thickness;
  if (o.weave_repeats_per_uv.x > 0.0 && o.weave_repeats_per_uv.y > 0.0)
    j[kWeaveRepeatsPerUv] = pair_json(o.weave_repeats_per_uv);
  if (o.colour) j[kColour] = vec3_json(*o.colour);
  if (!o.display_name.empty()) j[kDisplayName] = o.display_name;
  if (!o.composition.empty()) j[kComposition] = o.composition;
  if (o.textured()) {
    json maps = json::array();
    for (const auto& m : o.thread_maps) maps.push_back(m ? section_map_json(*m, texture_index(*m)) : json());
    j[kThreadMaps] = maps;
  }
  if (o.normal_map) {
    json n = section_map_json(o.normal_map->map, texture_index(o.normal_map->map));
    n[kNormalScale] = o.normal_map->scale;
    n["colour_space"] = "linear";  // the reader samples it unconverted (sample_stored_texture)
    j[kNormalMap] = n;
  }
  return j;
}

}  // namespace weft
