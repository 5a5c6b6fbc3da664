#include "scene/gltf_loadable.h"

#include <cstdint>
#include <cstring>

#include <nlohmann/json.hpp>

namespace weft {

namespace {

using json = nlohmann::json;

constexpr const char* kMeshoptExtensions[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};
constexpr const char* kDraco = "KHR_draco_mesh_compression";
// One zero byte: tinygltf needs data for every buffer.
constexpr const char* kStandIn = "data:application/octet-stream;base64,AA==";

bool fill_meshopt_fallbacks(json& j) {
  if (!j.contains("buffers") || !j["buffers"].is_array()) return false;
  bool changed = false;
  for (auto& b : j["buffers"]) {
    if (!b.is_object() || b.contains("uri") || !b.contains("extensions") || !b["extensions"].is_object()) continue;
    for (const char* name : kMeshoptExtensions) {
      const auto it = b["extensions"].find(name);
      if (it == b["extensions"].end() || !it->is_object() || it->value("fallback", false) != true) continue;
      b["uri"] = kStandIn;
      b["byteLength"] = 1;
      changed = true;
      break;
    }
  }
  return changed;
}

bool point_draco_indices_at_their_view(json& j) {
  if (!j.contains("meshes") || !j["meshes"].is_array() || !j.contains("accessors") || !j["accessors"].is_array())
    return false;
  json& accessors = j["accessors"];
  bool changed = false;
  for (auto& mesh : j["meshes"]) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    for (auto& p : mesh["primitives"]) {
      if (!p.is_object() || !p.contains("indices") || !p["indices"].is_number_unsigned() || !p.contains("extensions") ||
          !p["extensions"].is_object() || !p["extensions"].contains(kDraco))
        continue;
      const json& draco = p["extensions"][kDraco];
      const size_t index = p["indices"].get<size_t>();
      if (!draco.is_object() || !draco.contains("bufferView") || !draco["bufferView"].is_number_unsigned() ||
          index >= accessors.size() || !accessors[index].is_object() || accessors[index].contains("bufferView"))
        continue;
      accessors[index]["bufferView"] = draco["bufferView"];
      changed = true;
    }
  }
  return changed;
}

bool adjust(json& j) {
  if (!j.is_object()) return false;
  const bool filled = fill_meshopt_fallbacks(j);
  const bool pointed = point_draco_indices_at_their_view(j);
  return filled || pointed;
}

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

uint32_t read_u32(const std::string& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

void append_u32(std::string& b, uint32_t v) { b.append(reinterpret_cast<const char*>(&v), 4); }

}  // namespace

std::string loadable_by_tinygltf(const std::string& bytes) {
  // The common case, neither extension named anywhere: no second parse.
  if (bytes.find("fallback") == std::string::npos && bytes.find(kDraco) == std::string::npos) return bytes;
  const bool binary = bytes.size() >= 20 && bytes.compare(0, 4, "glTF") == 0;
  if (!binary) {
    json j = json::parse(bytes, nullptr, false);
    return adjust(j) ? dump(j) : bytes;
  }
  // GLB: header (magic, version, length), the JSON chunk (length, "JSON", text), then the rest.
  const uint32_t json_length = read_u32(bytes, 12);
  if (bytes.compare(16, 4, "JSON") != 0 || json_length > bytes.size() - 20) return bytes;
  json j = json::parse(bytes.substr(20, json_length), nullptr, false);
  if (!adjust(j)) return bytes;
  std::string text = dump(j);
  while (text.size() % 4) text.push_back(' ');  // chunks stay 4-byte aligned
  const std::string rest = bytes.substr(20 + json_length);
  std::string out = bytes.substr(0, 8);
  append_u32(out, static_cast<uint32_t>(12 + 8 + text.size() + rest.size()));
  append_u32(out, static_cast<uint32_t>(text.size()));
  out += "JSON";
  out += text;
  out += rest;
  return out;
}

}  // namespace weft
