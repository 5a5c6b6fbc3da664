#include "scene/thread_maps.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/normal_map_frame.h"
#include "scene/object_schema.h"

namespace weft {

glm::dvec2 transformed_uv(const TextureTransform& t, glm::dvec2 uv) {
  const double c = std::cos(t.rotation), s = std::sin(t.rotation);
  const glm::dvec2 scaled = t.scale * uv;
  return {t.offset.x + c * scaled.x + s * scaled.y, t.offset.y - s * scaled.x + c * scaled.y};
}

glm::dmat3 texture_matrix(const TextureTransform& t) {
  const double c = std::cos(t.rotation), s = std::sin(t.rotation);
  // Columns: the images of u, v and the constant 1.
  return glm::dmat3(glm::dvec3(c * t.scale.x, -s * t.scale.x, 0.0), glm::dvec3(s * t.scale.y, c * t.scale.y, 0.0),
                    glm::dvec3(t.offset, 1.0));
}

glm::dvec3 thread_tint(const SceneObject& o, int thread, glm::dvec2 uv) {
  const auto& m = o.thread_maps[thread];
  if (!m || !m->image) return glm::dvec3(1.0);
  return sample_texture(*m->image, transformed_uv(m->transform, uv));
}

glm::dvec3 normal_map_tangent(const SceneObject& o, glm::dvec2 uv) {
  if (!o.normal_map || !o.normal_map->map.image) return glm::dvec3(0.0, 0.0, 1.0);
  const ThreadMap& m = o.normal_map->map;
  return tangent_space_normal(sample_stored_texture(*m.image, transformed_uv(m.transform, uv)), o.normal_map->scale);
}

std::string texture_transform_problem(const TextureTransform& t) {
  constexpr double kLimit = 1e6;
  for (double x : {t.offset.x, t.offset.y, t.scale.x, t.scale.y, t.rotation})
    if (!std::isfinite(x)) return "not finite";
  if (std::abs(t.offset.x) > kLimit || std::abs(t.offset.y) > kLimit) return "offset beyond ±10^6";
  if (std::abs(t.scale.x) > kLimit || std::abs(t.scale.y) > kLimit) return "scale beyond ±10^6";
  if (t.scale.x == 0.0 || t.scale.y == 0.0) return "a scale of 0";
  if (std::abs(t.rotation) > kLimit) return "rotation beyond ±10^6";
  return "";
}

std::shared_ptr<const TextureImage> load_texture_file(const std::filesystem::path& file, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw SceneError(what + ": no image file " + file.string());
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw SceneError(what + ": cannot read " + file.string() + " (" + ec.message() + ")");
  if (size > kMaxTextureFileBytes)
    throw SceneError(what + ": " + file.string() + " has " + std::to_string(size) + " bytes, more than an image may (" +
                     std::to_string(kMaxTextureFileBytes) + ")");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(what + ": cannot open " + file.string());
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return std::make_shared<const TextureImage>(decode_texture(bytes, what + ": " + file.string()));
  } catch (const TextureError& e) {
    throw SceneError(e.what());
  }
}

ThreadMap parse_thread_map(const nlohmann::json& j, const std::string& where, const std::filesystem::path& base_dir,
                           TextureFiles& files) {
  if (!j.is_object()) throw SceneError(where + ": expected {\"image\", \"offset\", \"scale\", \"rotation\"}");
  for (const auto& [key, value] : j.items())
    if (key != "image" && key != "offset" && key != "scale" && key != "rotation")
      throw SceneError(where + "." + key + ": unknown (known: image, offset, scale, rotation)");
  if (!j.contains("image") || !j["image"].is_string() || j["image"].get<std::string>().empty())
    throw SceneError(where + ".image: expected an image file (PNG or JPEG)");
  ThreadMap m;
  const std::string named = j["image"].get<std::string>();
  const std::filesystem::path file = (base_dir / named).lexically_normal();
  m.name = std::filesystem::path(named).filename().string();
  m.transform = read_texture_transform(j, where);
  auto it = files.find(file.string());
  if (it == files.end()) {
    if (files.size() >= kMaxSceneTextures)
      throw SceneError(where + ": more than " + std::to_string(kMaxSceneTextures) + " images in one scene");
    it = files.emplace(file.string(), load_texture_file(file, where + ".image")).first;
  }
  m.image = it->second;
  return m;
}

NormalMap parse_normal_map(const nlohmann::json& j, const std::string& where, const std::filesystem::path& base_dir,
                           TextureFiles& files) {
  if (!j.is_object())
    throw SceneError(where + ": expected {\"image\", \"offset\", \"scale\", \"rotation\", \"normal_scale\"}");
  for (const auto& [key, value] : j.items())
    if (key != "image" && key != "offset" && key != "scale" && key != "rotation" && key != "normal_scale")
      throw SceneError(where + "." + key + ": unknown (known: image, offset, scale, rotation, normal_scale)");
  NormalMap m;
  if (j.contains("normal_scale")) m.scale = normal_scale_from_json(j["normal_scale"], where + ".normal_scale");
  nlohmann::json map = j;
  map.erase("normal_scale");
  m.map = parse_thread_map(map, where, base_dir, files);
  return m;
}

}  // namespace weft
