#include "scene/gltf_materials.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <span>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "scene/gltf_cloth_names.h"
#include "scene/gltf_sheen_fabric.h"
#include "scene/object_schema.h"
#include "scene/thread_maps.h"

namespace weft {

namespace {

using nlohmann::json;

// tinygltf's parsed value as JSON, for the readers scene files and bundles share.
json to_json(const tinygltf::Value& v) {
  if (v.IsBool()) return v.Get<bool>();
  if (v.IsInt()) return v.Get<int>();
  if (v.IsReal()) return v.Get<double>();
  if (v.IsString()) return v.Get<std::string>();
  if (v.IsArray()) {
    json out = json::array();
    for (size_t k = 0; k < v.ArrayLen(); ++k) out.push_back(to_json(v.Get(int(k))));
    return out;
  }
  if (v.IsObject()) {
    json out = json::object();
    for (const std::string& key : v.Keys()) out[key] = to_json(v.Get(key));
    return out;
  }
  return nullptr;
}

// A material's extras.weft, {} when it has none or it is not an object.
json weft_extras(const tinygltf::Material& mat) {
  if (!mat.extras.IsObject() || !mat.extras.Has("weft") || !mat.extras.Get("weft").IsObject()) return json::object();
  return to_json(mat.extras.Get("weft"));
}

bool is_preset(const std::filesystem::path& dir, const std::string& name) {
  if (dir.empty() || name.empty()) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  std::error_code ec;
  return std::filesystem::is_regular_file(dir / (name + ".json"), ec);
}

// A material name as Blender exports a copy of it ("linen_plain.001"): the name without its
// numbered suffix, or the name itself.
std::string without_copy_suffix(const std::string& name) {
  const auto dot = name.rfind('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == name.size()) return name;
  for (size_t i = dot + 1; i < name.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return name;
  return name.substr(0, dot);
}

std::string material_where(const tinygltf::Material& mat, size_t index) {
  return "materials[" + std::to_string(index) + "] ('" + mat.name + "')";
}

}  // namespace

std::string material_label(const tinygltf::Model& model, size_t slot) {
  return slot == 0 ? std::string("(default)") : material_where(model.materials[slot - 1], slot - 1);
}

GltfMaterials::GltfMaterials(const tinygltf::Model& model, std::string origin, std::filesystem::path base_dir,
                             const GltfImportOptions& options, std::vector<std::string>& notes)
    : m_(model), origin_(std::move(origin)), base_dir_(std::move(base_dir)), options_(options), notes_(notes) {
  slots_.assign(m_.materials.size() + 1, Slot{});
  for (size_t i = 0; i < m_.materials.size(); ++i) resolve(i);
  const bool any_cloth = std::any_of(slots_.begin(), slots_.end(), [](const Slot& s) { return !s.fabric.empty(); });
  if (!any_cloth && !options_.fallback_fabric.empty())
    for (Slot& s : slots_) s.fabric = options_.fallback_fabric;
}

void GltfMaterials::fail(const std::string& what) const { throw SceneError(origin_ + ": " + what); }

void GltfMaterials::resolve(size_t index) {
  const tinygltf::Material& mat = m_.materials[index];
  Slot& slot = slots_[index + 1];
  const json weft = weft_extras(mat);
  const std::string where = material_where(mat, index) + ".extras.weft";
  try {
    slot.optical_thickness = read_optical_thickness(weft, where);
    slot.weave_repeats_per_uv = read_weave_repeats_per_uv(weft, where);
    slot.display_name = read_label_text(weft, "display_name", where);
    slot.composition = read_label_text(weft, "composition", where);
  } catch (const SceneError& e) {
    fail(e.what());
  }
  if (auto it = options_.fabric_overrides.find(mat.name); it != options_.fabric_overrides.end())
    slot.fabric = it->second;
  else if (weft.contains("fabric"))
    slot.fabric = named_fabric(weft, where);
  else if (is_preset(options_.fabrics_dir, mat.name))
    slot.fabric = mat.name;
  else if (is_preset(options_.fabrics_dir, without_copy_suffix(mat.name)))
    slot.fabric = without_copy_suffix(mat.name);
  else
    slot.fabric = inferred_fabric(index);
}

std::string GltfMaterials::named_fabric(const json& weft, const std::string& where) const {
  std::string named;
  try {
    named = read_fabric(weft, where);
  } catch (const SceneError& e) {
    fail(e.what());
  }
  if (is_preset(options_.fabrics_dir, named)) return named;
  const std::filesystem::path file = (base_dir_ / named).lexically_normal();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    fail(where + ".fabric: '" + named + "' is neither a fabric preset nor a file (looked for " + file.string() + ")");
  return file.string();
}

std::string GltfMaterials::inferred_fabric(size_t index) {
  if (options_.fabrics_dir.empty()) return "";  // no presets to take: the caller wants geometry only
  const tinygltf::Material& mat = m_.materials[index];
  const std::string label = "material '" + mat.name + "'";
  const ClothNameVerdict name = cloth_name_verdict(mat.name);
  const auto words = [&] {
    std::string out;
    for (const std::string& w : name.words) out += (out.empty() ? "" : ", ") + w;
    return out;
  };
  using Kind = ClothNameVerdict::Kind;
  // A hard material's name outweighs a sheen: exporters put sheen on lacquered wood and brushed
  // metal too, and a leg drawn as velvet is worse than a cushion drawn flat.
  if (name.kind == Kind::hard) {
    if (mat.extensions.count(kSheenExtension))
      notes_.push_back(label + " not taken as cloth by its " + kSheenExtension + ": its name says " + words());
    return "";
  }
  std::optional<SheenFactors> sheen;
  try {
    sheen = read_sheen_factors(mat, material_where(mat, index), notes_);
  } catch (const SceneError& e) {
    fail(e.what());
  }
  if (sheen && !sheen_is_on(*sheen)) sheen.reset();
  std::string fabric, why;
  if (name.kind == Kind::preset) {
    fabric = name.preset;  // the author's word for the cloth outweighs its sheen
    why = "name: " + words();
  } else if (sheen) {
    fabric = sheen_preset(*sheen);
    why = std::string(kSheenExtension) + ": " + describe_sheen(*sheen);
  } else if (name.kind == Kind::generic) {
    fabric = kDefaultClothPreset;
    why = "name: " + words();
  } else {
    if (name.kind == Kind::ambiguous)
      notes_.push_back(label + " not taken as cloth by its name: its words disagree (" + words() + ")");
    return "";
  }
  if (!is_preset(options_.fabrics_dir, fabric)) {
    notes_.push_back(label + " would be cloth (" + why + ") in preset " + fabric + ", which " +
                     options_.fabrics_dir.string() + " lacks: taken as Lambertian");
    return "";
  }
  // The colour follows the sheen wherever there is one: a velvet named so is still a dark
  // ground under its sheen's colour.
  if (sheen) slots_[index + 1].sheen_colour = sheen_thread_colour(*sheen, fabric);
  notes_.push_back(label + " taken as cloth (" + why + "), preset " + fabric);
  return fabric;
}

std::optional<glm::dvec3> GltfMaterials::cloth_colour(size_t slot) const {
  if (slot == 0) return std::nullopt;
  if (slots_[slot].sheen_colour) return slots_[slot].sheen_colour;
  const tinygltf::Material& mat = m_.materials[slot - 1];
  // tinygltf fills an absent factor with the default; `values` holds only what the file says.
  if (!mat.values.count("baseColorFactor")) return std::nullopt;
  const auto& f = mat.pbrMetallicRoughness.baseColorFactor;
  const std::string where = material_where(mat, slot - 1) + ".pbrMetallicRoughness.baseColorFactor";
  try {
    return product_colour(std::vector<double>(f.begin(), f.begin() + std::min<size_t>(f.size(), 3)), where);
  } catch (const SceneError& e) {
    fail(e.what());
  }
}

void GltfMaterials::dress(SceneObject& o, size_t slot) {
  const Slot& s = slots_[slot];
  if (s.fabric.empty()) {
    o.material = Material::lambertian;
    if (slot == 0) return;
    const auto& f = m_.materials[slot - 1].pbrMetallicRoughness.baseColorFactor;
    if (f.size() >= 3)
      for (int c = 0; c < 3; ++c) o.albedo[c] = std::isfinite(f[c]) ? std::clamp(f[c], 0.0, 1.0) : 0.5;
    return;
  }
  o.material = Material::cloth;
  o.fabric = s.fabric;
  o.optical_thickness = s.optical_thickness;
  o.weave_repeats_per_uv = s.weave_repeats_per_uv;
  if (slot > 0) {
    o.colour = cloth_colour(slot);
    o.thread_maps = cloth_maps(slot - 1);
    o.normal_map = cloth_normal_map(slot - 1);
  }
  if (o.normal_map && o.mesh.uvs.empty())
    fail(material_label(m_, slot) + ": its normalTexture needs TEXCOORD_0 on every primitive, and one has none");
  if (o.textured() && o.mesh.uvs.empty())
    fail(material_label(m_, slot) + ": its texture needs TEXCOORD_0 on every primitive, and one has none");
  o.display_name = s.display_name;
  o.composition = s.composition;
}

std::shared_ptr<const TextureImage> GltfMaterials::image(int index, const std::string& where) {
  if (index < 0 || size_t(index) >= m_.images.size())
    fail(where + ": image " + std::to_string(index) + " does not exist (" + std::to_string(m_.images.size()) + " images)");
  if (auto it = images_.find(index); it != images_.end()) return it->second;
  if (images_.size() >= kMaxSceneTextures)
    fail(where + ": more than " + std::to_string(kMaxSceneTextures) + " images on cloth (the importer's limit)");
  const tinygltf::Image& im = m_.images[size_t(index)];
  const std::string what = origin_ + ": " + where + " (images[" + std::to_string(index) + "]" +
                           (im.name.empty() ? std::string() : " '" + im.name + "'") + ")";
  std::shared_ptr<const TextureImage> decoded;
  try {
    if (im.bufferView >= 0) {
      if (size_t(im.bufferView) >= m_.bufferViews.size())
        throw SceneError(what + ": buffer view " + std::to_string(im.bufferView) + " does not exist");
      const tinygltf::BufferView& v = m_.bufferViews[size_t(im.bufferView)];
      if (v.buffer < 0 || size_t(v.buffer) >= m_.buffers.size())
        throw SceneError(what + ": buffer " + std::to_string(v.buffer) + " does not exist");
      const auto& data = m_.buffers[size_t(v.buffer)].data;
      if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
        throw SceneError(what + ": buffer view " + std::to_string(im.bufferView) + " runs past the end of its buffer");
      decoded = std::make_shared<const TextureImage>(
          decode_texture(std::span<const std::uint8_t>(data.data() + v.byteOffset, v.byteLength), what));
    } else if (im.as_is && !im.image.empty()) {  // a data URI
      decoded = std::make_shared<const TextureImage>(decode_texture(im.image, what));
    } else if (!im.uri.empty()) {
      if (im.uri.find("://") != std::string::npos) throw SceneError(what + ": '" + im.uri + "' is not a local file");
      decoded = load_texture_file((base_dir_ / im.uri).lexically_normal(), what);
    } else {
      throw SceneError(what + ": the image has no data (no uri, no bufferView)");
    }
  } catch (const TextureError& e) {
    throw SceneError(e.what());
  }
  images_.emplace(index, decoded);
  return decoded;
}

ThreadMap GltfMaterials::thread_map(const json* transform, int texture, int texcoord, const std::string& where) {
  if (texture < 0 || size_t(texture) >= m_.textures.size())
    fail(where + ".index: texture " + std::to_string(texture) + " does not exist (" + std::to_string(m_.textures.size()) +
         " textures)");
  ThreadMap m;
  if (transform) {
    const std::string tw = where + ".extensions." + kTextureTransform;
    try {
      m.transform = read_texture_transform(*transform, tw);
    } catch (const SceneError& e) {
      fail(e.what());
    }
    if (transform->contains("texCoord")) {
      if (!(*transform)["texCoord"].is_number()) fail(tw + ".texCoord: expected a number");
      texcoord = int((*transform)["texCoord"].get<double>());
    }
  }
  if (texcoord != 0) fail(where + ": reads TEXCOORD_" + std::to_string(texcoord) + "; Weft keeps TEXCOORD_0 only");
  const tinygltf::Texture& t = m_.textures[size_t(texture)];
  if (t.source < 0) fail(where + ": texture " + std::to_string(texture) + " has no image (source)");
  m.image = image(t.source, where);
  const tinygltf::Image& im = m_.images[size_t(t.source)];
  m.name = !im.name.empty() ? im.name : !im.uri.empty() ? std::filesystem::path(im.uri).filename().string()
                                                        : "image_" + std::to_string(t.source);
  return m;
}

std::array<std::optional<ThreadMap>, 2> GltfMaterials::cloth_maps(size_t index) {
  const tinygltf::Material& mat = m_.materials[index];
  const std::string at = material_where(mat, index);
  std::array<std::optional<ThreadMap>, 2> out;
  const tinygltf::TextureInfo& base = mat.pbrMetallicRoughness.baseColorTexture;
  const json weft = weft_extras(mat);
  const bool weft_own = weft.contains("weft_texture");
  if (base.index < 0) {
    if (weft_own) fail(at + ".extras.weft.weft_texture: give the warp's pbrMetallicRoughness.baseColorTexture too");
    return out;
  }
  const auto ext = base.extensions.find(kTextureTransform);
  const json base_transform = ext == base.extensions.end() ? json() : to_json(ext->second);
  out[0] = thread_map(ext == base.extensions.end() ? nullptr : &base_transform, base.index, base.texCoord,
                      at + ".pbrMetallicRoughness.baseColorTexture");
  out[1] = out[0];
  if (weft_own) {
    const std::string w = at + ".extras.weft.weft_texture";
    const json& v = weft["weft_texture"];
    if (!v.is_object() || !v.contains("index") || !v["index"].is_number())
      fail(w + ": expected a texture reference {\"index\", \"extensions\": {\"" + kTextureTransform + "\": ...}}");
    const json* transform = nullptr;
    if (v.contains("extensions") && v["extensions"].contains(kTextureTransform))
      transform = &v["extensions"][kTextureTransform];
    const int texcoord = v.contains("texCoord") && v["texCoord"].is_number() ? int(v["texCoord"].get<double>()) : 0;
    out[1] = thread_map(transform, int(v["index"].get<double>()), texcoord, w);
  }
  return out;
}

std::optional<NormalMap> GltfMaterials::cloth_normal_map(size_t index) {
  const tinygltf::Material& mat = m_.materials[index];
  const tinygltf::NormalTextureInfo& info = mat.normalTexture;
  if (info.index < 0) return std::nullopt;
  const std::string at = material_where(mat, index) + ".normalTexture";
  NormalMap n;
  try {
    n.scale = normal_scale_from_json(info.scale, at + ".scale");
  } catch (const SceneError& e) {
    fail(e.what());
  }
  const auto ext = info.extensions.find(kTextureTransform);
  const json transform = ext == info.extensions.end() ? json() : to_json(ext->second);
  n.map = thread_map(ext == info.extensions.end() ? nullptr : &transform, info.index, info.texCoord, at);
  return n;
}

}  // namespace weft
