#pragma once
// One triangle primitive written into a glTF as a product pipeline writes it: plain floats,
// EXT_meshopt_compression as gltfpack writes it, or KHR_draco_mesh_compression as Blender
// writes it. The compression test and the gltf_compress tool share these encoders, so the
// files the test checks are the files the corpus ships.
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace weft::test {

inline constexpr int kFloat = 5126, kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
                     kUnsignedInt = 5125;

// A primitive's vertices as float arrays; normals and uvs may be empty (the primitive has none).
struct SourceMesh {
  std::vector<float> positions, normals, uvs;  // 3, 3, 2 per vertex
  std::vector<uint32_t> indices;
  size_t vertices() const { return positions.size() / 3; }
};

// A glTF under construction: its JSON and buffer 0's bytes. Meshopt's decoded views live in
// buffer 1, a fallback that holds no data.
struct GltfFile {
  nlohmann::json j = {{"asset", {{"version", "2.0"}}},
                      {"bufferViews", nlohmann::json::array()},
                      {"accessors", nlohmann::json::array()},
                      {"buffers", nlohmann::json::array({nlohmann::json::object()})}};
  std::string data;  // buffer 0

  // Appends `bytes` to buffer 0 (4-byte aligned); returns their offset.
  size_t append(const void* bytes, size_t n);
  // A buffer view over `n` new bytes of buffer 0; returns its index.
  int view(const void* bytes, size_t n, size_t stride = 0);
  // An accessor (view −1: none, its data comes from an extension); returns its index.
  int accessor(int view, int component, size_t count, const char* type, bool normalized = false);
  // Lists `extensions` as used and required (each once).
  void require(std::initializer_list<const char*> extensions);
  // The JSON with buffer 0 as a base64 data URI, or (uri not empty) as the external file `uri`.
  std::string text(const std::string& uri = "");
  // The same as a .glb: buffer 0 is the BIN chunk.
  std::string glb();
};

// Each returns the primitive's JSON ("attributes", "indices", extensions; no material) after
// adding its views and accessors to `f`, and lists the extensions it needs.
nlohmann::json plain_primitive(GltfFile& f, const SourceMesh& m);
// Positions as floats, normals octahedral (8 bits), UVs exponential (15-bit mantissa), indices
// as TRIANGLES; needs KHR_mesh_quantization for the byte normals.
nlohmann::json meshopt_primitive(GltfFile& f, const SourceMesh& m);
// Quantization: positions 14 bits, normals 10, UVs 12; the accessors declare the decoded counts.
// Throws std::runtime_error when Draco cannot encode the mesh.
nlohmann::json draco_primitive(GltfFile& f, const SourceMesh& m);

}  // namespace weft::test
