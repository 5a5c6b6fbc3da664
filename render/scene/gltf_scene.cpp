#include "scene/gltf_scene.h"
#include "scene/mesh_orientation.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "scene/gltf_cloth_names.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_loadable.h"
#include "scene/gltf_meshopt.h"
#include "scene/gltf_names.h"
#include "scene/gltf_sheen_fabric.h"
#include "scene/thread_maps.h"

namespace weft {

namespace {

constexpr const char* kDefaultEnvironment = "studio";

// glTF (+Y up) to Weft (+Z up): (x, y, z) → (x, −z, y), a rotation about +x.
const glm::dmat4 kToWeft(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(0, -1, 0, 0),
                         glm::dvec4(0, 0, 0, 1));

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Images are decoded by the importer, and only those a cloth's texture uses (thread_maps.h, with
// its caps). tinygltf hands a data URI's decoded bytes here, kept as they are; a bufferView's
// image is read by the importer within its buffer's bounds, an external file from its uri.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                      int size, void*) {
  if (image->bufferView < 0 && bytes && size > 0) {
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
  }
  return true;
}

constexpr const char* kTextureTransform = "KHR_texture_transform";
// Compressed and quantized geometry, decoded before any accessor is read (gltf_draco.h,
// gltf_meshopt.h) or read as it is (integer accessors).
constexpr const char* kDracoCompression = "KHR_draco_mesh_compression";
constexpr const char* kMeshoptCompression = "EXT_meshopt_compression";
constexpr const char* kKhrMeshoptCompression = "KHR_meshopt_compression";
constexpr const char* kMeshQuantization = "KHR_mesh_quantization";

// External buffers: only regular files within the size cap (no devices, no FIFOs, nothing that
// would take the whole memory), and nothing is ever written.
bool read_buffer_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    if (err) *err += "File not found : " + path + "\n";
    return false;
  }
  if (std::filesystem::file_size(path, ec) > kGltfMaxFileBytes) {
    if (err) *err += "buffer file " + path + " exceeds the importer's size limit\n";
    return false;
  }
  return tinygltf::ReadWholeFile(out, err, path, nullptr);
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "the importer writes no files\n";
  return false;
}

// A validated view of one accessor's elements inside its buffer.
struct AccessorData {
  const unsigned char* data = nullptr;
  size_t count = 0, stride = 0;
  int component_type = 0, components = 0;
  bool normalized = false;

  double component(size_t element, int c) const {
    const unsigned char* p = data + element * stride;
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p + 4 * c, 4);
        return v;
      }
      // Normalized signed integers per glTF 2.0 (3.11): max(c / 127, −1), so that −128 is −1 too.
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double v = static_cast<int8_t>(p[c]);
        return normalized ? std::max(v / 127.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const double v = p[c];
        return normalized ? v / 255.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v;
        std::memcpy(&v, p + 2 * c, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p + 2 * c, 2);
        return normalized ? v / 65535.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p + 4 * c, 4);
        return v;
      }
    }
    return 0.0;
  }
};

Camera framed_camera(const Scene& s);

class Importer {
public:
  Importer(const tinygltf::Model& model, std::string origin, std::filesystem::path base_dir,
           const GltfImportOptions& options)
      : m_(model), origin_(std::move(origin)), base_dir_(std::move(base_dir)), options_(options) {}

  Scene run();

private:
  [[noreturn]] void fail(const std::string& what) const { throw SceneError(origin_ + ": " + what); }

  // Integer components: whether the accessor must say normalized (NORMAL, TANGENT), must not
  // (indices), or either (POSITION, TEXCOORD_0: KHR_mesh_quantization).
  enum class Integers { normalized, plain, either };
  AccessorData accessor(int index, const std::string& where, std::initializer_list<int> types,
                        std::initializer_list<int> component_types, Integers integers = Integers::either);
  void resolve_materials();
  // What a material that neither an override, its extras nor a preset's name makes cloth is taken
  // as from its name and its KHR_materials_sheen (docs/design.md §1, "glTF materials as cloth"):
  // a preset name, or "" for Lambertian; notes what it decided.
  std::string inferred_fabric(size_t index);
  // The product colour of cloth material `index`: its baseColorFactor's RGB when the file gives
  // one (absent, glTF's default white is no colour of the product's: the fabric's own stays); for
  // a material with a sheen made cloth by its name or sheen, the colour sheen_thread_colour gives.
  std::optional<glm::dvec3> cloth_colour(size_t index) const;
  // Cloth material `index`'s textures (baseColorTexture on both threads, extras.weft.weft_texture
  // the weft's own); none when it has no baseColorTexture.
  std::array<std::optional<ThreadMap>, 2> cloth_maps(size_t index);
  // Cloth material `index`'s normalTexture (with its scale), none when it has none.
  std::optional<NormalMap> cloth_normal_map(size_t index);
  ThreadMap thread_map(const tinygltf::Value* info, int texture, int texcoord, const std::string& where);
  std::shared_ptr<const TextureImage> image(int index, const std::string& where);
  void read_variants();  // KHR_materials_variants: the file's list of variants
  void map_variants(const tinygltf::Primitive& p, const std::string& where);  // one primitive's mappings
  std::vector<Colourway> colourways(const std::vector<std::string>& object_names);
  std::vector<std::pair<int, glm::dmat4>> mesh_instances();
  void add_primitive(const tinygltf::Primitive& p, const glm::dmat4& world, const std::string& where);

  const tinygltf::Model& m_;
  std::string origin_;
  std::filesystem::path base_dir_;
  const GltfImportOptions& options_;

  // Per material (index + 1; 0 is glTF's default material): its fabric ("" = Lambertian).
  std::vector<std::string> fabrics_;
  std::vector<double> thickness_;  // per material (index + 1): extras.weft.optical_thickness, 0 when absent
  std::vector<glm::dvec2> repeats_;  // per material (index + 1): extras.weft.weave_repeats_per_uv, 0 when absent
  std::vector<std::string> variants_;  // KHR_materials_variants' variant names, in order
  // Per material (index + 1): the thread colour of a material with a sheen made cloth by its name
  // or sheen (sheen_thread_colour), none otherwise.
  std::vector<std::optional<glm::dvec3>> sheen_colours_;
  std::vector<std::string> notes_;  // what the import decided for the log (Scene::warnings)
  // Per variant, per material (index + 1): the materials (index + 1) that material's primitives wear in it.
  std::vector<std::vector<std::set<size_t>>> variant_materials_;
  // Per material (index + 1): extras.weft.display_name and .composition, empty when absent.
  std::vector<std::string> display_names_, compositions_;
  std::map<int, std::shared_ptr<const TextureImage>> images_;  // decoded, by image index
  std::vector<TriangleMesh> groups_;
  std::vector<MeshRepairReport> reports_;
  // A closed primitive whose normals or winding point into it (mesh_orientation.h), turned once
  // the camera is known: not where the camera stands inside it (a room seen from within).
  struct InwardPart {
    size_t group = 0, first_vertex = 0, vertices = 0, first_triangle = 0, triangles = 0;
    glm::dvec3 lo{0.0}, hi{0.0};
    MeshOrientation orientation;
    std::string where;
  };
  std::vector<InwardPart> inward_;
  void turn_inward_parts(const std::optional<glm::dvec3>& camera);
  size_t vertices_ = 0, triangles_ = 0;
};

AccessorData Importer::accessor(int index, const std::string& where, std::initializer_list<int> types,
                                std::initializer_list<int> component_types, Integers integers) {
  if (index < 0 || static_cast<size_t>(index) >= m_.accessors.size())
    fail(where + ": accessor " + std::to_string(index) + " does not exist (" + std::to_string(m_.accessors.size()) +
         " accessors)");
  const tinygltf::Accessor& a = m_.accessors[index];
  const std::string at = where + " (accessor " + std::to_string(index) + ")";
  auto listed = [](auto names, auto list) {
    std::string out;
    for (int x : list) out += (out.empty() ? "" : ", ") + names(x);
    return out;
  };
  if (std::find(types.begin(), types.end(), a.type) == types.end())
    fail(at + ": wrong element type " + gltf_element_type_name(a.type) + " (expected " +
         listed(gltf_element_type_name, types) + ")");
  if (std::find(component_types.begin(), component_types.end(), a.componentType) == component_types.end())
    fail(at + ": wrong component type " + gltf_component_type_name(a.componentType) + " (expected " +
         listed(gltf_component_type_name, component_types) + ")");
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && integers == Integers::normalized && !a.normalized)
    fail(at + ": component type " + gltf_component_type_name(a.componentType) +
         " without normalized (integers here must be normalized, KHR_mesh_quantization)");
  if (integers == Integers::plain && a.normalized)
    fail(at + ": component type " + gltf_component_type_name(a.componentType) + " marked normalized (indices never are)");
  if (a.sparse.isSparse) fail(at + ": sparse accessors are not supported");
  if (a.bufferView < 0)
    fail(at + ": has no buffer view (its data would come from an extension; is the file compressed with one Weft "
              "does not read?)");
  if (static_cast<size_t>(a.bufferView) >= m_.bufferViews.size())
    fail(at + ": buffer view " + std::to_string(a.bufferView) + " does not exist");
  const tinygltf::BufferView& v = m_.bufferViews[a.bufferView];
  if (v.buffer < 0 || static_cast<size_t>(v.buffer) >= m_.buffers.size())
    fail(at + ": buffer " + std::to_string(v.buffer) + " does not exist");
  const size_t buffer_size = m_.buffers[v.buffer].data.size();
  if (v.byteOffset > buffer_size || v.byteLength > buffer_size - v.byteOffset)
    fail(at + ": buffer view " + std::to_string(a.bufferView) + " runs past the end of buffer " +
         std::to_string(v.buffer) + " (" + std::to_string(buffer_size) + " bytes; missing or short buffer file?)");
  AccessorData d;
  d.component_type = a.componentType;
  d.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  d.normalized = a.normalized;
  d.count = a.count;
  const size_t element = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(a.componentType)) * d.components;
  d.stride = v.byteStride != 0 ? v.byteStride : element;
  if (d.stride < element) fail(at + ": byte stride " + std::to_string(d.stride) + " is smaller than an element");
  if (d.count > std::max(kGltfMaxVertices, 3 * kGltfMaxTriangles))
    fail(at + ": " + std::to_string(d.count) + " elements exceed the importer's limit");
  if (d.count == 0) fail(at + ": no elements");
  const size_t span = (d.count - 1) * d.stride + element;
  if (a.byteOffset > v.byteLength || span > v.byteLength - a.byteOffset)
    fail(at + ": " + std::to_string(d.count) + " elements run past the end of buffer view " +
         std::to_string(a.bufferView));
  d.data = m_.buffers[v.buffer].data.data() + v.byteOffset + a.byteOffset;
  return d;
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

void Importer::resolve_materials() {
  fabrics_.assign(m_.materials.size() + 1, "");
  thickness_.assign(m_.materials.size() + 1, 0.0);
  repeats_.assign(m_.materials.size() + 1, glm::dvec2(0.0));
  display_names_.assign(m_.materials.size() + 1, "");
  compositions_.assign(m_.materials.size() + 1, "");
  sheen_colours_.assign(m_.materials.size() + 1, std::nullopt);
  bool any_cloth = false;
  for (size_t i = 0; i < m_.materials.size(); ++i) {
    const tinygltf::Material& mat = m_.materials[i];
    std::string& fabric = fabrics_[i + 1];
    if (mat.extras.IsObject() && mat.extras.Has("weft") && mat.extras.Get("weft").Has("optical_thickness")) {
      const tinygltf::Value& t = mat.extras.Get("weft").Get("optical_thickness");
      const std::string where = "materials[" + std::to_string(i) + "] ('" + mat.name + "').extras.weft.optical_thickness";
      const double tau = t.IsNumber() ? t.GetNumberAsDouble() : -1.0;
      if (!(tau > 0.0 && tau <= kMaxOpticalThickness))
        fail(where + ": expected a number in (0, " + std::to_string(int(kMaxOpticalThickness)) + "]");
      thickness_[i + 1] = tau;
    }
    if (mat.extras.IsObject() && mat.extras.Has("weft") && mat.extras.Get("weft").Has("weave_repeats_per_uv")) {
      const tinygltf::Value& r = mat.extras.Get("weft").Get("weave_repeats_per_uv");
      const std::string where = "materials[" + std::to_string(i) + "] ('" + mat.name + "').extras.weft.weave_repeats_per_uv";
      const auto value = [&](int k) { return r.IsArray() && r.ArrayLen() == 2 && r.Get(k).IsNumber() ? r.Get(k).GetNumberAsDouble() : -1.0; };
      const glm::dvec2 repeats{value(0), value(1)};
      if (!(repeats.x > 0.0 && repeats.y > 0.0 && repeats.x <= kMaxWeaveRepeatsPerUv && repeats.y <= kMaxWeaveRepeatsPerUv))
        fail(where + ": expected [along u, along v], two numbers in (0, " + std::to_string(int(kMaxWeaveRepeatsPerUv)) + "]");
      repeats_[i + 1] = repeats;
    }
    for (auto [key, into] : {std::pair{"display_name", &display_names_}, std::pair{"composition", &compositions_}}) {
      if (!(mat.extras.IsObject() && mat.extras.Has("weft") && mat.extras.Get("weft").Has(key))) continue;
      const tinygltf::Value& t = mat.extras.Get("weft").Get(key);
      const std::string where = "materials[" + std::to_string(i) + "] ('" + mat.name + "').extras.weft." + key;
      if (!t.IsString()) fail(where + ": expected a string");
      if (const std::string why = fabric_text_problem(t.Get<std::string>()); !why.empty()) fail(where + ": " + why);
      (*into)[i + 1] = t.Get<std::string>();
    }
    if (auto it = options_.fabric_overrides.find(mat.name); it != options_.fabric_overrides.end()) {
      fabric = it->second;
    } else if (mat.extras.IsObject() && mat.extras.Has("weft") && mat.extras.Get("weft").Has("fabric")) {
      const tinygltf::Value& f = mat.extras.Get("weft").Get("fabric");
      const std::string where = "materials[" + std::to_string(i) + "] ('" + mat.name + "').extras.weft.fabric";
      if (!f.IsString() || f.Get<std::string>().empty()) fail(where + ": expected a preset name or a fabric file");
      const std::string named = f.Get<std::string>();
      if (is_preset(options_.fabrics_dir, named)) {
        fabric = named;
      } else {
        const std::filesystem::path file = (base_dir_ / named).lexically_normal();
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec))
          fail(where + ": '" + named + "' is neither a fabric preset nor a file (looked for " + file.string() + ")");
        fabric = file.string();
      }
    } else if (is_preset(options_.fabrics_dir, mat.name)) {
      fabric = mat.name;
    } else if (is_preset(options_.fabrics_dir, without_copy_suffix(mat.name))) {
      fabric = without_copy_suffix(mat.name);
    } else {
      fabric = inferred_fabric(i);
    }
    any_cloth = any_cloth || !fabric.empty();
  }
  if (!any_cloth && !options_.fallback_fabric.empty()) std::fill(fabrics_.begin(), fabrics_.end(), options_.fallback_fabric);
}

std::string Importer::inferred_fabric(size_t index) {
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
    sheen = read_sheen_factors(mat, "materials[" + std::to_string(index) + "] ('" + mat.name + "')", notes_);
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
  // The colour follows the sheen wherever there is one: a velvet named so is still a dark
  // ground under its sheen's colour.
  if (sheen) sheen_colours_[index + 1] = sheen_thread_colour(*sheen, fabric);
  if (!is_preset(options_.fabrics_dir, fabric)) {
    notes_.push_back(label + " would be cloth (" + why + ") in preset " + fabric + ", which " +
                     options_.fabrics_dir.string() + " lacks: taken as Lambertian");
    sheen_colours_[index + 1].reset();
    return "";
  }
  notes_.push_back(label + " taken as cloth (" + why + "), preset " + fabric);
  return fabric;
}

std::optional<glm::dvec3> Importer::cloth_colour(size_t index) const {
  if (sheen_colours_[index + 1]) return sheen_colours_[index + 1];
  const tinygltf::Material& mat = m_.materials[index];
  // tinygltf fills an absent factor with the default; `values` holds only what the file says.
  if (!mat.values.count("baseColorFactor")) return std::nullopt;
  const auto& f = mat.pbrMetallicRoughness.baseColorFactor;
  const std::string where = "materials[" + std::to_string(index) + "] ('" + mat.name + "').pbrMetallicRoughness.baseColorFactor";
  try {
    return product_colour(std::vector<double>(f.begin(), f.begin() + std::min<size_t>(f.size(), 3)), where);
  } catch (const SceneError& e) {
    fail(e.what());
  }
}

std::shared_ptr<const TextureImage> Importer::image(int index, const std::string& where) {
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

// A number pair of KHR_texture_transform ("offset", "scale"), or `fallback` when absent.
glm::dvec2 transform_pair(const tinygltf::Value& t, const char* key, glm::dvec2 fallback, const std::string& where,
                          const std::function<void(const std::string&)>& fail) {
  if (!t.Has(key)) return fallback;
  const tinygltf::Value& v = t.Get(key);
  if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
    fail(where + "." + key + ": expected two numbers");
  return {v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble()};
}

ThreadMap Importer::thread_map(const tinygltf::Value* transform, int texture, int texcoord, const std::string& where) {
  if (texture < 0 || size_t(texture) >= m_.textures.size())
    fail(where + ".index: texture " + std::to_string(texture) + " does not exist (" + std::to_string(m_.textures.size()) +
         " textures)");
  ThreadMap m;
  const std::function<void(const std::string&)> failing = [this](const std::string& w) { fail(w); };
  if (transform) {
    const std::string tw = where + ".extensions." + kTextureTransform;
    if (!transform->IsObject()) fail(tw + ": expected an object");
    m.transform.offset = transform_pair(*transform, "offset", glm::dvec2(0.0), tw, failing);
    m.transform.scale = transform_pair(*transform, "scale", glm::dvec2(1.0), tw, failing);
    if (transform->Has("rotation")) {
      if (!transform->Get("rotation").IsNumber()) fail(tw + ".rotation: expected a number (radians)");
      m.transform.rotation = transform->Get("rotation").GetNumberAsDouble();
    }
    if (transform->Has("texCoord")) {
      if (!transform->Get("texCoord").IsNumber()) fail(tw + ".texCoord: expected a number");
      texcoord = int(transform->Get("texCoord").GetNumberAsDouble());
    }
    if (const std::string why = texture_transform_problem(m.transform); !why.empty()) fail(tw + ": " + why);
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

std::array<std::optional<ThreadMap>, 2> Importer::cloth_maps(size_t index) {
  const tinygltf::Material& mat = m_.materials[index];
  const std::string at = "materials[" + std::to_string(index) + "] ('" + mat.name + "')";
  std::array<std::optional<ThreadMap>, 2> out;
  const tinygltf::TextureInfo& base = mat.pbrMetallicRoughness.baseColorTexture;
  const bool weft_own = mat.extras.IsObject() && mat.extras.Has("weft") && mat.extras.Get("weft").Has("weft_texture");
  if (base.index < 0) {
    if (weft_own) fail(at + ".extras.weft.weft_texture: give the warp's pbrMetallicRoughness.baseColorTexture too");
    return out;
  }
  const auto ext = base.extensions.find(kTextureTransform);
  out[0] = thread_map(ext == base.extensions.end() ? nullptr : &ext->second, base.index, base.texCoord,
                      at + ".pbrMetallicRoughness.baseColorTexture");
  out[1] = out[0];
  if (weft_own) {
    const std::string w = at + ".extras.weft.weft_texture";
    const tinygltf::Value& v = mat.extras.Get("weft").Get("weft_texture");
    if (!v.IsObject() || !v.Has("index") || !v.Get("index").IsNumber())
      fail(w + ": expected a texture reference {\"index\", \"extensions\": {\"" + kTextureTransform + "\": ...}}");
    const tinygltf::Value* transform = nullptr;
    if (v.Has("extensions") && v.Get("extensions").Has(kTextureTransform))
      transform = &v.Get("extensions").Get(kTextureTransform);
    const int texcoord = v.Has("texCoord") && v.Get("texCoord").IsNumber() ? int(v.Get("texCoord").GetNumberAsDouble()) : 0;
    out[1] = thread_map(transform, int(v.Get("index").GetNumberAsDouble()), texcoord, w);
  }
  return out;
}

std::optional<NormalMap> Importer::cloth_normal_map(size_t index) {
  const tinygltf::Material& mat = m_.materials[index];
  const tinygltf::NormalTextureInfo& info = mat.normalTexture;
  if (info.index < 0) return std::nullopt;
  const std::string at = "materials[" + std::to_string(index) + "] ('" + mat.name + "').normalTexture";
  if (!std::isfinite(info.scale) || std::abs(info.scale) > 1e6) fail(at + ".scale: expected a finite number");
  const auto ext = info.extensions.find(kTextureTransform);
  return NormalMap{thread_map(ext == info.extensions.end() ? nullptr : &ext->second, info.index, info.texCoord, at),
                   info.scale};
}

constexpr const char* kVariants = "KHR_materials_variants";

void Importer::read_variants() {
  const auto it = m_.extensions.find(kVariants);
  if (it == m_.extensions.end()) return;
  const std::string where = std::string("extensions.") + kVariants + ".variants";
  const tinygltf::Value& list = it->second.IsObject() ? it->second.Get("variants") : tinygltf::Value();
  // tinygltf reads an empty list as no value: both are refused alike.
  if (!list.IsArray() || list.ArrayLen() == 0) fail(where + ": expected a non-empty list of variants ({\"name\": ...})");
  for (size_t k = 0; k < list.ArrayLen(); ++k) {
    const tinygltf::Value& v = list.Get(int(k));
    const bool named = v.IsObject() && v.Has("name") && v.Get("name").IsString() && !v.Get("name").Get<std::string>().empty();
    if (!named) fail(where + "[" + std::to_string(k) + "]: has no name");
    variants_.push_back(v.Get("name").Get<std::string>());
  }
  variant_materials_.assign(variants_.size(), std::vector<std::set<size_t>>(m_.materials.size() + 1));
}

// A whole number in [0, n) from a glTF value, or −1.
long index_below(const tinygltf::Value& v, size_t n) {
  if (!v.IsNumber()) return -1;
  const double x = v.GetNumberAsDouble();
  return x >= 0.0 && x < double(n) && x == std::floor(x) ? long(x) : -1;
}

void Importer::map_variants(const tinygltf::Primitive& p, const std::string& where) {
  const auto it = p.extensions.find(kVariants);
  const std::string w = where + ".extensions." + kVariants + ".mappings";
  if (variants_.empty()) {
    if (it != p.extensions.end()) fail(w + ": the file lists no variants (extensions." + kVariants + ".variants)");
    return;
  }
  const size_t own = size_t(p.material + 1);
  std::vector<size_t> worn(variants_.size(), own);
  if (it != p.extensions.end()) {
    const tinygltf::Value& maps = it->second.IsObject() ? it->second.Get("mappings") : tinygltf::Value();
    if (!maps.IsArray()) fail(w + ": expected a list of {\"material\", \"variants\"}");
    for (size_t k = 0; k < maps.ArrayLen(); ++k) {
      const tinygltf::Value& m = maps.Get(int(k));
      const std::string mw = w + "[" + std::to_string(k) + "]";
      const tinygltf::Value& material = m.IsObject() ? m.Get("material") : tinygltf::Value();
      const long mi = index_below(material, m_.materials.size());
      if (mi < 0)
        fail(mw + ".material: " + (material.IsNumber() ? "material " + std::to_string(material.GetNumberAsDouble()) + " does not exist" : std::string("missing or not a number")) +
             " (" + std::to_string(m_.materials.size()) + " materials)");
      const tinygltf::Value& vs = m.Get("variants");
      if (!vs.IsArray() || vs.ArrayLen() == 0) fail(mw + ".variants: expected a non-empty list of variant indices");
      for (size_t j = 0; j < vs.ArrayLen(); ++j) {
        const long vi = index_below(vs.Get(int(j)), variants_.size());
        if (vi < 0)
          fail(mw + ".variants[" + std::to_string(j) + "]: not one of the file's " + std::to_string(variants_.size()) + " variants");
        worn[size_t(vi)] = size_t(mi + 1);
      }
    }
  }
  for (size_t v = 0; v < variants_.size(); ++v) variant_materials_[v][own].insert(worn[v]);
}

// A material's name for messages (index + 1; 0 is glTF's default material).
std::string material_label(const tinygltf::Model& m, size_t i) {
  return i == 0 ? std::string("(default)") : "materials[" + std::to_string(i - 1) + "] ('" + m.materials[i - 1].name + "')";
}

std::vector<Colourway> Importer::colourways(const std::vector<std::string>& object_names) {
  std::vector<Colourway> out;
  for (size_t v = 0; v < variants_.size(); ++v) {
    Colourway c;
    c.name = variants_[v];
    const std::string in = "variant '" + c.name + "'";
    for (size_t i = 0; i < object_names.size(); ++i) {
      const std::set<size_t>& worn = variant_materials_[v][i];
      if (object_names[i].empty() || worn.empty()) continue;
      if (worn.size() > 1)
        fail(in + ": the primitives of " + material_label(m_, i) +
             " wear different materials; Weft draws one look per material (give them one material in this variant)");
      const size_t t = *worn.begin();
      const bool cloth = !fabrics_[i].empty(), becomes_cloth = !fabrics_[t].empty();
      if (cloth != becomes_cloth)
        fail(in + ": " + material_label(m_, i) + (cloth ? " is cloth and " : " is not cloth and ") + material_label(m_, t) +
             (cloth ? " is not" : " is") + "; a colourway changes a cloth object's fabric and colour only");
      if (cloth) c.objects[object_names[i]] = ClothLook{fabrics_[t], t > 0 ? cloth_colour(t - 1) : std::nullopt};
    }
    out.push_back(std::move(c));
  }
  return out;
}

glm::dmat4 local_transform(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());  // column-major, as glm
  glm::dmat4 t(1.0);
  if (n.translation.size() == 3) t = glm::translate(t, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
  if (n.rotation.size() == 4) {
    glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);  // glTF: x, y, z, w
    const double l = glm::length(q);
    if (l > 0.0) t = t * glm::mat4_cast(q / l);
  }
  if (n.scale.size() == 3) t = glm::scale(t, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
  return t;
}

// Every node's world transform (already in Weft's frame), walking the scene's roots; a node
// reached twice means the hierarchy is not a tree (cycles included) and is refused.
std::vector<std::pair<int, glm::dmat4>> Importer::mesh_instances() {
  const size_t n = m_.nodes.size();
  std::vector<int> roots;
  if (!m_.scenes.empty()) {
    const int s = m_.defaultScene >= 0 ? m_.defaultScene : 0;
    if (static_cast<size_t>(s) >= m_.scenes.size()) fail("scene " + std::to_string(s) + " does not exist");
    roots = m_.scenes[s].nodes;
  } else {  // no scenes: every node nobody names as a child
    std::vector<bool> child(n, false);
    for (const auto& node : m_.nodes)
      for (int c : node.children)
        if (c >= 0 && static_cast<size_t>(c) < n) child[c] = true;
    for (size_t i = 0; i < n; ++i)
      if (!child[i]) roots.push_back(static_cast<int>(i));
  }
  std::vector<bool> seen(n, false);
  std::vector<std::pair<int, glm::dmat4>> stack, out;
  for (int r : roots) stack.emplace_back(r, kToWeft);
  while (!stack.empty()) {
    auto [i, parent] = stack.back();
    stack.pop_back();
    if (i < 0 || static_cast<size_t>(i) >= n) fail("node " + std::to_string(i) + " does not exist");
    if (seen[i]) fail("node " + std::to_string(i) + " is reached twice: the node hierarchy is not a tree");
    seen[i] = true;
    const tinygltf::Node& node = m_.nodes[i];
    for (double x : node.matrix)
      if (!std::isfinite(x)) fail("nodes[" + std::to_string(i) + "].matrix is not finite");
    for (const auto* v : {&node.translation, &node.rotation, &node.scale})
      for (double x : *v)
        if (!std::isfinite(x)) fail("nodes[" + std::to_string(i) + "] has a non-finite transform");
    const glm::dmat4 world = parent * local_transform(node);
    if (node.mesh >= 0 || node.camera >= 0) out.emplace_back(i, world);
    for (int c : node.children) stack.emplace_back(c, world);
  }
  return out;
}

void Importer::add_primitive(const tinygltf::Primitive& p, const glm::dmat4& world, const std::string& where) {
  if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES)
    fail(where + ": mode " + std::to_string(p.mode) + " (" + gltf_mode_name(p.mode) +
         ") is not TRIANGLES (4), the only mode Weft reads");
  if (p.material < -1 || p.material >= static_cast<int>(m_.materials.size()))
    fail(where + ": material " + std::to_string(p.material) + " does not exist");
  map_variants(p, where);
  const std::string& fabric = fabrics_[p.material + 1];
  const bool cloth = !fabric.empty();
  auto attribute = [&](const char* name) {
    auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
  };
  const int pos_i = attribute("POSITION"), nrm_i = attribute("NORMAL"), uv_i = attribute("TEXCOORD_0"),
            tan_i = attribute("TANGENT");
  if (pos_i < 0) fail(where + ": no POSITION attribute");
  constexpr int F = TINYGLTF_COMPONENT_TYPE_FLOAT, B = TINYGLTF_COMPONENT_TYPE_BYTE,
                UB = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, S = TINYGLTF_COMPONENT_TYPE_SHORT,
                US = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  // Integer positions and UVs (KHR_mesh_quantization) are read as numbers; the node transform
  // that the quantizer wrote scales them back.
  const AccessorData pos = accessor(pos_i, where + ".POSITION", {TINYGLTF_TYPE_VEC3}, {F, B, UB, S, US});
  const size_t nv = pos.count;
  if (nv > kGltfMaxVertices - vertices_)
    fail("more than " + std::to_string(kGltfMaxVertices) + " vertices in all (the importer's limit)");

  TriangleMesh mesh;
  mesh.positions.resize(nv);
  for (size_t v = 0; v < nv; ++v) mesh.positions[v] = {pos.component(v, 0), pos.component(v, 1), pos.component(v, 2)};
  auto same_count = [&](const AccessorData& a, const char* name) {
    if (a.count != nv)
      fail(where + "." + name + ": " + std::to_string(a.count) + " elements for " + std::to_string(nv) + " positions");
  };
  if (nrm_i >= 0) {
    const AccessorData a = accessor(nrm_i, where + ".NORMAL", {TINYGLTF_TYPE_VEC3}, {F, B, S}, Integers::normalized);
    same_count(a, "NORMAL");
    mesh.normals.resize(nv);
    for (size_t v = 0; v < nv; ++v) mesh.normals[v] = {a.component(v, 0), a.component(v, 1), a.component(v, 2)};
  }
  if (uv_i >= 0) {
    const AccessorData a = accessor(uv_i, where + ".TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, {F, B, UB, S, US});
    same_count(a, "TEXCOORD_0");
    mesh.uvs.resize(nv);
    for (size_t v = 0; v < nv; ++v) mesh.uvs[v] = {a.component(v, 0), a.component(v, 1)};
  }
  std::vector<glm::dvec3> tangents;
  if (tan_i >= 0) {
    const AccessorData a = accessor(tan_i, where + ".TANGENT", {TINYGLTF_TYPE_VEC4}, {F, B, S}, Integers::normalized);
    same_count(a, "TANGENT");
    tangents.resize(nv);
    for (size_t v = 0; v < nv; ++v) {
      tangents[v] = {a.component(v, 0), a.component(v, 1), a.component(v, 2)};
      if (!finite(tangents[v])) fail(where + ".TANGENT: vertex " + std::to_string(v) + " is not finite (NaN/Inf)");
    }
  }
  // Cloth with neither: the importer's fixed warp (compute_warp_directions) and no weave, which
  // needs UVs to lay its threads out; the fabric level needs only a frame.
  if (cloth && tangents.empty() && mesh.uvs.empty())
    notes_.push_back(where + ": cloth (fabric '" + fabric +
                     "') without TANGENT or TEXCOORD_0: its warp is a fixed direction (x × its normal), and no "
                     "weave is drawn up close");

  if (p.indices >= 0) {
    const AccessorData a = accessor(p.indices, where + ".indices", {TINYGLTF_TYPE_SCALAR},
                                    {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                    Integers::plain);
    if (a.count % 3 != 0) fail(where + ".indices: " + std::to_string(a.count) + " indices are not whole triangles");
    if (a.count / 3 > kGltfMaxTriangles - triangles_)
      fail("more than " + std::to_string(kGltfMaxTriangles) + " triangles in all (the importer's limit)");
    mesh.triangles.resize(a.count / 3);
    for (size_t t = 0; t < a.count / 3; ++t)
      for (int k = 0; k < 3; ++k) {
        const double idx = a.component(3 * t + k, 0);
        if (idx >= static_cast<double>(nv))
          fail(where + ".indices: index " + std::to_string(static_cast<uint64_t>(idx)) + " is out of range (" +
               std::to_string(nv) + " vertices)");
        mesh.triangles[t][k] = static_cast<uint32_t>(idx);
      }
  } else {
    if (nv % 3 != 0) fail(where + ": " + std::to_string(nv) + " unindexed vertices are not whole triangles");
    mesh.triangles.resize(nv / 3);
    for (size_t t = 0; t < nv / 3; ++t)
      mesh.triangles[t] = {uint32_t(3 * t), uint32_t(3 * t + 1), uint32_t(3 * t + 2)};
  }

  // Into Weft's frame: points by the world matrix, normals by its inverse transpose, tangents
  // by its linear part; a mirroring transform flips the winding so that faces keep their side.
  const glm::dmat3 linear(world);
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
  if (!(std::abs(glm::determinant(linear)) > 0.0)) fail(where + ": its node transform is singular");
  for (auto& q : mesh.positions) q = glm::dvec3(world * glm::dvec4(q, 1.0));
  for (auto& q : mesh.normals) q = normal_matrix * q;
  for (auto& q : tangents) q = linear * q;
  if (glm::determinant(linear) < 0.0)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);

  MeshRepairReport report;
  try {
    // UV-degenerate triangles matter only where the warp comes from the UVs.
    report = repair_mesh(mesh, cloth && tangents.empty() && !mesh.uvs.empty(), where);
    if (mesh.normals.empty()) compute_vertex_normals(mesh);
    for (size_t v = 0; v < nv; ++v) {
      const double l = glm::length(mesh.normals[v]);
      if (!(l > 1e-12)) fail(where + ".NORMAL: vertex " + std::to_string(v) + " has a zero-length normal");
      mesh.normals[v] /= l;
    }
    if (tangents.empty()) {
      compute_warp_directions(mesh);
    } else {
      mesh.warps = std::move(tangents);
      // A TANGENT along the normal (or NaN) gets a fixed warp: any keeps the frame valid.
      for (size_t v = 0; v < nv; ++v) mesh.warps[v] = unit_tangent(mesh.warps[v], mesh.normals[v]);
    }
  } catch (const MeshError& e) {
    fail(e.what());
  }

  // Merge into the material's object.
  TriangleMesh& g = groups_[p.material + 1];
  if (const MeshOrientation o = mesh_orientation(mesh); o.closed && o.inward()) {
    InwardPart part{size_t(p.material + 1), g.positions.size(), mesh.positions.size(), g.triangles.size(),
                    mesh.triangles.size(), mesh.positions.front(), mesh.positions.front(), o, where};
    for (const auto& q : mesh.positions) part.lo = glm::min(part.lo, q), part.hi = glm::max(part.hi, q);
    inward_.push_back(std::move(part));
  }
  MeshRepairReport& r = reports_[p.material + 1];
  r.degenerate_triangles_dropped += report.degenerate_triangles_dropped;
  r.unused_vertices += report.unused_vertices;
  const uint32_t base = static_cast<uint32_t>(g.positions.size());
  const bool had_uvs = g.positions.empty() || !g.uvs.empty();
  g.positions.insert(g.positions.end(), mesh.positions.begin(), mesh.positions.end());
  g.normals.insert(g.normals.end(), mesh.normals.begin(), mesh.normals.end());
  g.warps.insert(g.warps.end(), mesh.warps.begin(), mesh.warps.end());
  if (had_uvs && !mesh.uvs.empty())
    g.uvs.insert(g.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
  else
    g.uvs.clear();  // UVs are kept only where every merged primitive has them
  for (const auto& t : mesh.triangles) g.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  vertices_ += nv;
  triangles_ += mesh.triangles.size();
}

// Looks at the bounds' centre from the front left and above (Weft's cameras face +y), far enough
// that the bounding sphere fills the vertical field of view.
Camera framed_camera(const Scene& s) {
  const bool any_cloth = !s.cloth_objects().empty();
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const auto& o : s.objects)
    if (!any_cloth || o.is_cloth())
      for (const auto& p : o.mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
  Camera c;
  c.fov_deg = 40.0;
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
  const double distance = 1.1 * radius / std::sin(0.5 * c.fov_deg * 3.14159265358979323846 / 180.0);
  c.target = centre;
  c.position = centre + distance * glm::normalize(glm::dvec3(0.45, -1.0, 0.55));
  c.up = {0, 0, 1};
  return c;
}

void Importer::turn_inward_parts(const std::optional<glm::dvec3>& camera) {
  for (const InwardPart& part : inward_) {
    const std::string what = std::string(part.orientation.normals_inward ? "normals" : "") +
                             (part.orientation.normals_inward && part.orientation.winding_inward ? " and " : "") +
                             (part.orientation.winding_inward ? "winding" : "");
    if (camera && glm::all(glm::greaterThanEqual(*camera, part.lo)) && glm::all(glm::lessThanEqual(*camera, part.hi))) {
      notes_.push_back(part.where + ": a closed part whose " + what + " point inwards, kept so: the camera is inside it");
      continue;
    }
    TriangleMesh& g = groups_[part.group];
    turn_outward(std::span(g.triangles).subspan(part.first_triangle, part.triangles),
                 std::span(g.normals).subspan(part.first_vertex, part.vertices), part.orientation);
    notes_.push_back(part.where + ": a closed part whose " + what +
                     " pointed inwards (its shading and shadows would come from inside it): turned outwards");
  }
}

Scene Importer::run() {
  resolve_materials();
  read_variants();
  groups_.assign(fabrics_.size(), {});
  reports_.assign(fabrics_.size(), {});
  Scene s;
  s.environment = kDefaultEnvironment;
  bool have_camera = false;
  for (const auto& [node, world] : mesh_instances()) {
    const tinygltf::Node& n = m_.nodes[node];
    if (n.camera >= 0 && !have_camera) {
      if (static_cast<size_t>(n.camera) >= m_.cameras.size()) fail("camera " + std::to_string(n.camera) + " does not exist");
      const tinygltf::Camera& c = m_.cameras[n.camera];
      if (c.type == "perspective") {
        const double fov = c.perspective.yfov * 180.0 / 3.14159265358979323846;
        if (!(fov > 1.0 && fov < 170.0))
          fail("cameras[" + std::to_string(n.camera) + "].yfov: must be in (1, 170) degrees, got " + std::to_string(fov));
        // A glTF camera looks down its local −Z with +Y up.
        s.camera.position = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
        const glm::dvec3 forward = glm::dvec3(world * glm::dvec4(0, 0, -1, 0));
        const glm::dvec3 up = glm::dvec3(world * glm::dvec4(0, 1, 0, 0));
        if (!(glm::length(forward) > 1e-12) || !(glm::length(glm::cross(forward, up)) > 1e-12 * glm::length(forward)))
          fail("nodes[" + std::to_string(node) + "]: camera transform is singular");
        s.camera.target = s.camera.position + glm::normalize(forward);
        s.camera.up = glm::normalize(up);
        s.camera.fov_deg = fov;
        have_camera = true;
      }
    }
    if (n.mesh < 0) continue;
    if (static_cast<size_t>(n.mesh) >= m_.meshes.size()) fail("mesh " + std::to_string(n.mesh) + " does not exist");
    const tinygltf::Mesh& mesh = m_.meshes[n.mesh];
    for (size_t p = 0; p < mesh.primitives.size(); ++p)
      add_primitive(mesh.primitives[p], world,
                    "meshes[" + std::to_string(n.mesh) + "].primitives[" + std::to_string(p) + "]");
  }
  turn_inward_parts(have_camera ? std::optional<glm::dvec3>(s.camera.position) : std::nullopt);
  std::vector<std::string> object_names(groups_.size());  // per material (index + 1), "" when it has no object
  for (size_t i = 0; i < groups_.size(); ++i) {
    if (groups_[i].triangles.empty()) continue;
    SceneObject o;
    o.name = i == 0 ? std::string("default") : m_.materials[i - 1].name;
    if (o.name.empty()) o.name = "material_" + std::to_string(i - 1);
    const std::string stem = o.name;
    for (int k = 2; std::any_of(s.objects.begin(), s.objects.end(), [&](const SceneObject& x) { return x.name == o.name; });
         ++k)
      o.name = stem + "_" + std::to_string(k);  // material names need not be unique
    o.mesh = std::move(groups_[i]);
    o.repair = reports_[i];
    if (!fabrics_[i].empty()) {
      o.material = Material::cloth;
      o.fabric = fabrics_[i];
      o.optical_thickness = thickness_[i];
      o.weave_repeats_per_uv = repeats_[i];
      if (i > 0) o.colour = cloth_colour(i - 1);
      if (i > 0) o.thread_maps = cloth_maps(i - 1);
      if (i > 0) o.normal_map = cloth_normal_map(i - 1);
      if (o.normal_map && o.mesh.uvs.empty())
        fail(material_label(m_, i) + ": its normalTexture needs TEXCOORD_0 on every primitive, and one has none");
      if (o.textured() && o.mesh.uvs.empty())
        fail(material_label(m_, i) + ": its texture needs TEXCOORD_0 on every primitive, and one has none");
      o.display_name = display_names_[i];
      o.composition = compositions_[i];
    } else {
      o.material = Material::lambertian;
      if (i > 0) {
        const auto& f = m_.materials[i - 1].pbrMetallicRoughness.baseColorFactor;
        if (f.size() >= 3)
          for (int c = 0; c < 3; ++c) o.albedo[c] = std::isfinite(f[c]) ? std::clamp(f[c], 0.0, 1.0) : 0.5;
      }
    }
    object_names[i] = o.name;
    s.objects.push_back(std::move(o));
  }
  if (s.objects.empty()) fail("no triangle meshes in the scene");
  s.colourways = colourways(object_names);
  try {
    check_colourways(s, origin_);
  } catch (const SceneError& e) {
    throw SceneError(std::string(e.what()) + " (from extensions." + kVariants + ")");
  }
  if (!have_camera) s.camera = framed_camera(s);
  for (const std::string& n : notes_) s.warnings.push_back(origin_ + ": " + n);
  return s;
}

}  // namespace

bool is_gltf_path(const std::string& name) {
  std::string ext = std::filesystem::path(name).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".gltf" || ext == ".glb";
}

Scene parse_gltf_scene(const std::string& bytes, const std::string& origin, const std::filesystem::path& base_dir,
                       const GltfImportOptions& options) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, nullptr);
  loader.SetFsCallbacks({tinygltf::FileExists, tinygltf::ExpandFilePath, read_buffer_file, refuse_write, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  bool ok = false;
  try {
    const std::string loadable = loadable_by_tinygltf(bytes);
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(loadable.data()),
                                              static_cast<unsigned int>(loadable.size()), base_dir.string())
                : loader.LoadASCIIFromString(&model, &err, &warn, loadable.data(), static_cast<unsigned int>(loadable.size()),
                                             base_dir.string());
  } catch (const std::exception& e) {
    ok = false;
    err = e.what();
  }
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    std::replace(err.begin(), err.end(), '\n', ';');
    throw SceneError(origin + ": not a usable glTF 2.0 file (" + (err.empty() ? std::string("no reason given") : err) + ")");
  }
  // A required extension Weft does not read is refused by name (its data would read as garbage),
  // an optional one is a remark for the log.
  const std::set<std::string> read = {kTextureTransform,   kVariants,         kDracoCompression, kMeshoptCompression,
                                      kKhrMeshoptCompression, kMeshQuantization, kSheenExtension};
  for (const std::string& e : model.extensionsRequired)
    if (!read.count(e))
      throw SceneError(origin + ": requires the glTF extension " + e +
                     ", which Weft cannot read (export the file without it)");
  std::vector<std::string> remarks;
  for (const std::string& e : model.extensionsUsed)
    if (!read.count(e)) remarks.push_back("uses the glTF extension " + e + ", which Weft ignores");
  decode_meshopt_buffer_views(model, origin);
  decode_draco_primitives(model, origin);
  Scene s = Importer(model, origin, base_dir, options).run();
  for (const std::string& r : remarks) s.warnings.push_back(origin + ": " + r);
  // tinygltf's warnings, one per line, for the log: what it let through is worth a look.
  std::stringstream lines(warn);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) s.warnings.push_back(origin + ": " + line);
  s.name = std::filesystem::path(origin).stem().string();
  s.description = "glTF " + origin;
  return s;
}

Scene load_gltf_scene(const std::filesystem::path& file, const GltfImportOptions& options) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw SceneError("cannot open glTF file " + file.string() + " (" + ec.message() + ")");
  if (size > kGltfMaxFileBytes)
    throw SceneError(file.string() + ": " + std::to_string(size) + " bytes exceed the importer's limit");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError("cannot open glTF file " + file.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_gltf_scene(ss.str(), file.string(), file.parent_path(), options);
}

}  // namespace weft
