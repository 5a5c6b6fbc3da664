// gltf_compress IN.gltf OUT.gltf --draco|--meshopt: rewrites a plain glTF's triangle meshes with
// KHR_draco_mesh_compression or EXT_meshopt_compression (the encoders of gltf_encode.h), keeping
// its nodes, materials, cameras and images, so that the test corpus (make_corpus.py) holds
// compressed files as Blender and gltfpack write them. Python cannot encode either format.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/gltf_encode.h"

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;
using weft::test::GltfFile;
using weft::test::SourceMesh;

constexpr const char* kUsage =
    "Usage: gltf_compress IN.gltf OUT.gltf --draco|--meshopt\n"
    "Rewrites IN's triangle meshes (float POSITION, NORMAL, TEXCOORD_0; indices of any unsigned type or none) compressed with\n"
    "KHR_draco_mesh_compression (--draco: positions 14 bits, normals 10, UVs 12) or EXT_meshopt_compression\n"
    "with KHR_mesh_quantization (--meshopt: lossless positions, 8-bit octahedral normals, 15-bit UVs).\n"
    "Writes OUT.gltf and OUT.bin beside it, and copies IN's image files there when OUT is elsewhere.\n";

struct Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw Failure("cannot read " + p.string());
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string from_base64(const std::string& text) {
  std::string out;
  uint32_t bits = 0;
  int have = 0;
  for (char c : text) {
    int v = c >= 'A' && c <= 'Z' ? c - 'A' : c >= 'a' && c <= 'z' ? c - 'a' + 26 : c >= '0' && c <= '9' ? c - '0' + 52
          : c == '+' ? 62 : c == '/' ? 63 : -1;
    if (v < 0) continue;  // padding
    bits = (bits << 6) | uint32_t(v);
    if ((have += 6) >= 8) out.push_back(char((bits >> (have -= 8)) & 0xff));
  }
  return out;
}

// The input's buffers, read, and its accessors as the encoders' float arrays.
class Input {
public:
  Input(json j, fs::path dir) : j_(std::move(j)), dir_(std::move(dir)) {
    for (const json& b : j_.value("buffers", json::array())) {
      const std::string uri = b.value("uri", "");
      if (uri.empty()) throw Failure("a buffer without a uri (a .glb's BIN chunk?): give a .gltf");
      const auto comma = uri.find(',');
      buffers_.push_back(uri.starts_with("data:") ? from_base64(uri.substr(comma + 1)) : read_file(dir_ / uri));
    }
  }

  // Accessor `index`'s elements as numbers, `components` per element.
  template <typename T>
  std::vector<T> read(int index, int components, const std::string& what) const {
    const json& a = j_.at("accessors").at(size_t(index));
    if (!a.contains("bufferView") || a.contains("sparse"))
      throw Failure(what + ": accessor " + std::to_string(index) + " has no plain data (already compressed?)");
    const json& v = j_.at("bufferViews").at(a["bufferView"].get<size_t>());
    const int type = a.at("componentType");
    const size_t size = type == weft::test::kUnsignedByte ? 1 : type == weft::test::kUnsignedShort ? 2 : 4;
    const bool floats = type == weft::test::kFloat;
    if (floats != std::is_floating_point_v<T> || (!floats && type != weft::test::kUnsignedByte &&
                                                  type != weft::test::kUnsignedShort && type != weft::test::kUnsignedInt))
      throw Failure(what + ": component type " + std::to_string(type) + " is not one this tool reads");
    const std::string& bytes = buffers_.at(v.at("buffer").get<size_t>());
    const size_t count = a.at("count"), element = size * size_t(components);
    const size_t stride = v.value("byteStride", element);
    const size_t start = v.value("byteOffset", size_t(0)) + a.value("byteOffset", size_t(0));
    if (count == 0 || start + (count - 1) * stride + element > bytes.size())
      throw Failure(what + ": accessor " + std::to_string(index) + " runs past its buffer");
    std::vector<T> out;
    out.reserve(count * size_t(components));
    for (size_t i = 0; i < count; ++i)
      for (int c = 0; c < components; ++c) {
        const char* p = bytes.data() + start + i * stride + size_t(c) * size;
        if (floats) {
          float f;
          std::memcpy(&f, p, 4);
          out.push_back(T(f));
        } else {
          uint32_t u = 0;
          std::memcpy(&u, p, size);  // little-endian, as glTF
          out.push_back(T(u));
        }
      }
    return out;
  }

  SourceMesh mesh(const json& primitive, const std::string& where) const {
    if (primitive.value("mode", 4) != 4) throw Failure(where + ": not TRIANGLES");
    if (primitive.contains("targets")) throw Failure(where + ": morph targets are not compressed by this tool");
    const json& at = primitive.at("attributes");
    for (const auto& [name, _] : at.items())
      if (name != "POSITION" && name != "NORMAL" && name != "TEXCOORD_0")
        throw Failure(where + ": attribute " + name + " (this tool carries POSITION, NORMAL and TEXCOORD_0)");
    SourceMesh m;
    m.positions = read<float>(at.at("POSITION"), 3, where + ".POSITION");
    if (at.contains("NORMAL")) m.normals = read<float>(at["NORMAL"], 3, where + ".NORMAL");
    if (at.contains("TEXCOORD_0")) m.uvs = read<float>(at["TEXCOORD_0"], 2, where + ".TEXCOORD_0");
    if (primitive.contains("indices")) {
      m.indices = read<uint32_t>(primitive["indices"], 1, where + ".indices");
    } else {
      for (uint32_t i = 0; i < m.vertices(); ++i) m.indices.push_back(i);
    }
    if ((!m.normals.empty() && m.normals.size() / 3 != m.vertices()) || (!m.uvs.empty() && m.uvs.size() / 2 != m.vertices()))
      throw Failure(where + ": attributes of different counts");
    // The encoders index the vertex arrays unchecked.
    if (m.indices.size() % 3 != 0 || std::any_of(m.indices.begin(), m.indices.end(), [&](uint32_t i) { return i >= m.vertices(); }))
      throw Failure(where + ".indices: not whole triangles of the primitive's vertices");
    return m;
  }

  // An image's bytes held in a buffer view.
  std::string view_bytes(size_t view) const {
    const json& v = j_.at("bufferViews").at(view);
    return buffers_.at(v.at("buffer").get<size_t>()).substr(v.value("byteOffset", size_t(0)), v.at("byteLength").get<size_t>());
  }

private:
  json j_;
  fs::path dir_;
  std::vector<std::string> buffers_;
};

int run(const fs::path& in_path, const fs::path& out_path, bool draco) {
  const json in = json::parse(read_file(in_path));
  const Input input(in, in_path.parent_path());
  GltfFile f;
  f.j = in;
  f.j["accessors"] = json::array();
  f.j["bufferViews"] = json::array();
  f.j["buffers"] = json::array({json::object()});
  size_t vertices = 0, triangles = 0, primitives = 0;
  for (size_t mi = 0; mi < f.j.value("meshes", json::array()).size(); ++mi)
    for (size_t pi = 0; pi < f.j["meshes"][mi]["primitives"].size(); ++pi) {
      json& p = f.j["meshes"][mi]["primitives"][pi];
      const SourceMesh m =
          input.mesh(p, "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) + "]");
      const json encoded = draco ? weft::test::draco_primitive(f, m) : weft::test::meshopt_primitive(f, m);
      p.erase("indices");
      p.update(encoded, true);  // merges into the primitive's own extensions (variants) too
      vertices += m.vertices();
      triangles += m.indices.size() / 3;
      ++primitives;
    }
  if (primitives == 0) throw Failure(in_path.string() + ": no meshes to compress");
  const fs::path out_dir = out_path.parent_path().empty() ? fs::path(".") : out_path.parent_path();
  fs::create_directories(out_dir);
  if (!f.j.contains("images")) f.j["images"] = json::array();
  for (json& image : f.j["images"]) {
    if (image.contains("bufferView")) {
      const std::string bytes = input.view_bytes(image["bufferView"]);
      image["bufferView"] = f.view(bytes.data(), bytes.size());
    } else if (image.contains("uri") && !image["uri"].get<std::string>().starts_with("data:")) {
      const fs::path from = in_path.parent_path() / image["uri"].get<std::string>(), to = out_dir / image["uri"].get<std::string>();
      if (fs::weakly_canonical(from) != fs::weakly_canonical(to)) {
        fs::create_directories(to.parent_path());
        fs::copy_file(from, to, fs::copy_options::overwrite_existing);
      }
    }
  }
  if (f.j.contains("images") && f.j["images"].empty()) f.j.erase("images");
  f.j["asset"]["generator"] = f.j["asset"].value("generator", "") + " (geometry compressed by gltf_compress)";
  const fs::path bin = fs::path(out_path).replace_extension(".bin");
  const std::string text = f.text(bin.filename().string());
  std::ofstream(bin, std::ios::binary) << f.data;
  std::ofstream(out_path, std::ios::binary) << text;
  std::cout << out_path.string() << ": " << primitives << " primitives, " << vertices << " vertices, " << triangles
            << " triangles, " << f.data.size() << " bytes of " << (draco ? "Draco" : "meshopt") << " data\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << kUsage;
    return 0;
  }
  if (args.size() != 3 || (args[2] != "--draco" && args[2] != "--meshopt")) {
    std::cerr << kUsage;
    return 2;
  }
  try {
    return run(args[0], args[1], args[2] == "--draco");
  } catch (const std::exception& e) {
    std::cerr << "gltf_compress: " << e.what() << "\n";
    return 1;
  }
}
