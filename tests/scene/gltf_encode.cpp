#include "scene/gltf_encode.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>

#include "support/base64_text.h"

namespace weft::test {

using json = nlohmann::json;

size_t GltfFile::append(const void* bytes, size_t n) {
  while (data.size() % 4) data.push_back('\0');
  const size_t at = data.size();
  data.append(static_cast<const char*>(bytes), n);
  return at;
}

int GltfFile::view(const void* bytes, size_t n, size_t stride) {
  json v = {{"buffer", 0}, {"byteOffset", append(bytes, n)}, {"byteLength", n}};
  if (stride) v["byteStride"] = stride;
  j["bufferViews"].push_back(v);
  return int(j["bufferViews"].size() - 1);
}

int GltfFile::accessor(int view, int component, size_t count, const char* type, bool normalized) {
  json a = {{"componentType", component}, {"count", count}, {"type", type}};
  if (view >= 0) a["bufferView"] = view;
  if (normalized) a["normalized"] = true;
  j["accessors"].push_back(a);
  return int(j["accessors"].size() - 1);
}

void GltfFile::require(std::initializer_list<const char*> extensions) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    json& list = j[key];
    if (!list.is_array()) list = json::array();
    for (const char* e : extensions)
      if (std::find(list.begin(), list.end(), e) == list.end()) list.push_back(e);
  }
}

std::string GltfFile::text(const std::string& uri) {
  j["buffers"][0]["byteLength"] = data.size();
  j["buffers"][0]["uri"] = uri.empty() ? "data:application/octet-stream;base64," + base64(data) : uri;
  return j.dump();
}

std::string GltfFile::glb() {
  j["buffers"][0]["byteLength"] = data.size();
  j["buffers"][0].erase("uri");
  std::string text = j.dump(), bin = data;
  while (text.size() % 4) text.push_back(' ');
  while (bin.size() % 4) bin.push_back('\0');
  std::string out = "glTF";
  auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  u32(2);
  u32(uint32_t(12 + 8 + text.size() + 8 + bin.size()));
  u32(uint32_t(text.size()));
  out += "JSON" + text;
  u32(uint32_t(bin.size()));
  out += std::string("BIN\0", 4) + bin;
  return out;
}

namespace {

// glTF requires POSITION's box; readers frame and cull by it.
void declare_bounds(GltfFile& f, int accessor, const SourceMesh& m) {
  std::vector<float> lo(3, 1e30f), hi(3, -1e30f);
  for (size_t v = 0; v < m.vertices(); ++v)
    for (int k = 0; k < 3; ++k) {
      lo[size_t(k)] = std::min(lo[size_t(k)], m.positions[3 * v + size_t(k)]);
      hi[size_t(k)] = std::max(hi[size_t(k)], m.positions[3 * v + size_t(k)]);
    }
  f.j["accessors"][size_t(accessor)]["min"] = lo;
  f.j["accessors"][size_t(accessor)]["max"] = hi;
}

}  // namespace

json plain_primitive(GltfFile& f, const SourceMesh& m) {
  const size_t n = m.vertices();
  json attributes = {{"POSITION", f.accessor(f.view(m.positions.data(), n * 12), kFloat, n, "VEC3")}};
  declare_bounds(f, attributes["POSITION"], m);
  if (!m.normals.empty()) attributes["NORMAL"] = f.accessor(f.view(m.normals.data(), n * 12), kFloat, n, "VEC3");
  if (!m.uvs.empty()) attributes["TEXCOORD_0"] = f.accessor(f.view(m.uvs.data(), n * 8), kFloat, n, "VEC2");
  return {{"attributes", attributes},
          {"indices", f.accessor(f.view(m.indices.data(), m.indices.size() * 4), kUnsignedInt, m.indices.size(), "SCALAR")}};
}

json meshopt_primitive(GltfFile& f, const SourceMesh& m) {
  const size_t n = m.vertices();
  if (f.j["buffers"].size() < 2)
    f.j["buffers"].push_back({{"byteLength", 0}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  json& fallback = f.j["buffers"][1];
  auto compressed = [&](const void* raw, size_t count, size_t stride, const std::string& mode, const std::string& filter) {
    std::vector<unsigned char> encoded;
    if (mode == "ATTRIBUTES") {
      encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
      encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), raw, count, stride));
    } else {
      encoded.resize(meshopt_encodeIndexBufferBound(count, n));
      encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), static_cast<const unsigned int*>(raw), count));
    }
    const size_t at = fallback["byteLength"].get<size_t>();
    json v = {{"buffer", 1}, {"byteOffset", at}, {"byteLength", count * stride}};
    if (mode == "ATTRIBUTES") v["byteStride"] = stride;
    json e = {{"buffer", 0}, {"byteOffset", f.append(encoded.data(), encoded.size())}, {"byteLength", encoded.size()},
              {"byteStride", stride}, {"count", count}, {"mode", mode}};
    if (filter != "NONE") e["filter"] = filter;
    v["extensions"]["EXT_meshopt_compression"] = e;
    fallback["byteLength"] = at + (count * stride + 3) / 4 * 4;
    f.j["bufferViews"].push_back(v);
    return int(f.j["bufferViews"].size() - 1);
  };
  json attributes = {{"POSITION", f.accessor(compressed(m.positions.data(), n, 12, "ATTRIBUTES", "NONE"), kFloat, n, "VEC3")}};
  declare_bounds(f, attributes["POSITION"], m);
  if (!m.normals.empty()) {
    std::vector<float> normals4(4 * n, 0.f);
    for (size_t v = 0; v < n; ++v)
      for (size_t k = 0; k < 3; ++k) normals4[4 * v + k] = m.normals[3 * v + k];
    std::vector<int8_t> oct(4 * n);
    meshopt_encodeFilterOct(oct.data(), n, 4, 8, normals4.data());
    attributes["NORMAL"] = f.accessor(compressed(oct.data(), n, 4, "ATTRIBUTES", "OCTAHEDRAL"), kByte, n, "VEC3", true);
  }
  if (!m.uvs.empty()) {
    std::vector<uint32_t> exp(2 * n);
    meshopt_encodeFilterExp(exp.data(), n, 8, 15, m.uvs.data());
    attributes["TEXCOORD_0"] = f.accessor(compressed(exp.data(), n, 8, "ATTRIBUTES", "EXPONENTIAL"), kFloat, n, "VEC2");
  }
  f.require({"EXT_meshopt_compression", "KHR_mesh_quantization"});
  return {{"attributes", attributes},
          {"indices", f.accessor(compressed(m.indices.data(), m.indices.size(), 4, "TRIANGLES", "NONE"), kUnsignedInt,
                                 m.indices.size(), "SCALAR")}};
}

json draco_primitive(GltfFile& f, const SourceMesh& m) {
  const size_t faces = m.indices.size() / 3;
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(int(faces));
  const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int nrm = m.normals.empty() ? -1 : builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  const int tex = m.uvs.empty() ? -1 : builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  for (size_t t = 0; t < faces; ++t) {
    const uint32_t* c = &m.indices[3 * t];
    const draco::FaceIndex face(static_cast<uint32_t>(t));
    builder.SetAttributeValuesForFace(pos, face, &m.positions[3 * c[0]], &m.positions[3 * c[1]], &m.positions[3 * c[2]]);
    if (nrm >= 0)
      builder.SetAttributeValuesForFace(nrm, face, &m.normals[3 * c[0]], &m.normals[3 * c[1]], &m.normals[3 * c[2]]);
    if (tex >= 0) builder.SetAttributeValuesForFace(tex, face, &m.uvs[2 * c[0]], &m.uvs[2 * c[1]], &m.uvs[2 * c[2]]);
  }
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  if (!mesh) throw std::runtime_error("Draco could not build the mesh");
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  draco::EncoderBuffer encoded;
  if (const draco::Status s = encoder.EncodeMeshToBuffer(*mesh, &encoded); !s.ok())
    throw std::runtime_error("Draco could not encode the mesh: " + s.error_msg_string());
  // The counts an exporter declares: those of the decoded mesh (Draco merges equal points).
  draco::DecoderBuffer in;
  in.Init(encoded.data(), encoded.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&in);
  if (!decoded.ok()) throw std::runtime_error("Draco cannot decode what it encoded: " + decoded.status().error_msg_string());
  const size_t points = decoded.value()->num_points();
  const int view = f.view(encoded.data(), encoded.size());
  json attributes = {{"POSITION", f.accessor(-1, kFloat, points, "VEC3")}};
  json ids = {{"POSITION", mesh->attribute(pos)->unique_id()}};
  declare_bounds(f, attributes["POSITION"], m);
  if (nrm >= 0) {
    attributes["NORMAL"] = f.accessor(-1, kFloat, points, "VEC3");
    ids["NORMAL"] = mesh->attribute(nrm)->unique_id();
  }
  if (tex >= 0) {
    attributes["TEXCOORD_0"] = f.accessor(-1, kFloat, points, "VEC2");
    ids["TEXCOORD_0"] = mesh->attribute(tex)->unique_id();
  }
  f.require({"KHR_draco_mesh_compression"});
  return {{"attributes", attributes},
          {"indices", f.accessor(-1, kUnsignedInt, 3 * decoded.value()->num_faces(), "SCALAR")},
          {"extensions", {{"KHR_draco_mesh_compression", {{"bufferView", view}, {"attributes", ids}}}}}};
}

}  // namespace weft::test
