#include "scene/gltf_draco.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

#include <draco/compression/decode.h>
#include <tiny_gltf.h>

#include "scene/gltf_names.h"
#include "scene/gltf_scene.h"
#include "scene/scene.h"

namespace weft {

namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";

// The attribute's value at every point, `components` values of type T each; false when Draco
// cannot convert them.
template <typename T>
bool attribute_values(const draco::PointAttribute& att, uint32_t points, int components, std::vector<unsigned char>& out) {
  out.resize(size_t(points) * components * sizeof(T));
  std::vector<T> value(static_cast<size_t>(components));
  for (uint32_t i = 0; i < points; ++i) {
    if (!att.ConvertValue<T>(att.mapped_index(draco::PointIndex(i)), int8_t(components), value.data())) return false;
    std::memcpy(out.data() + size_t(i) * components * sizeof(T), value.data(), components * sizeof(T));
  }
  return true;
}

// A new accessor like `like` over `data` in a buffer of its own; returns its index.
int add_accessor(tinygltf::Model& m, tinygltf::Accessor like, std::vector<unsigned char> data, const std::string& name) {
  tinygltf::Buffer buffer;
  buffer.name = name;
  tinygltf::BufferView view;
  view.buffer = static_cast<int>(m.buffers.size());
  view.byteLength = data.size();
  buffer.data = std::move(data);
  m.buffers.push_back(std::move(buffer));
  like.bufferView = static_cast<int>(m.bufferViews.size());
  like.byteOffset = 0;
  like.sparse = {};
  m.bufferViews.push_back(std::move(view));
  m.accessors.push_back(std::move(like));
  return static_cast<int>(m.accessors.size() - 1);
}

void decode_primitive(tinygltf::Model& m, tinygltf::Primitive& p, const std::string& at) {
  const tinygltf::Value ext = p.extensions.at(kDraco);
  auto fail = [&](const std::string& why) { throw SceneError(at + ": " + why); };
  auto index = [&](const tinygltf::Value& v, size_t n) -> long {
    const double x = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    return x >= 0.0 && x < double(n) && x == std::floor(x) ? long(x) : -1;
  };
  if (!ext.IsObject()) fail("expected an object");
  const long view_index = index(ext.Get("bufferView"), m.bufferViews.size());
  if (view_index < 0) fail("bufferView: missing, or not one of the file's " + std::to_string(m.bufferViews.size()) + " buffer views");
  const tinygltf::BufferView& view = m.bufferViews[size_t(view_index)];
  if (view.buffer < 0 || size_t(view.buffer) >= m.buffers.size())
    fail("buffer view " + std::to_string(view_index) + ": buffer " + std::to_string(view.buffer) + " does not exist");
  const auto& source = m.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > source.size() || view.byteLength > source.size() - view.byteOffset)
    fail("buffer view " + std::to_string(view_index) + " runs past the end of buffer " + std::to_string(view.buffer) +
         " (" + std::to_string(source.size()) + " bytes; missing or short buffer file?)");
  const tinygltf::Value& attributes = ext.Get("attributes");
  if (!attributes.IsObject() || attributes.Keys().empty()) fail("attributes: expected {\"POSITION\": id, ...}");

  draco::DecoderBuffer encoded;
  encoded.Init(reinterpret_cast<const char*>(source.data() + view.byteOffset), view.byteLength);
  draco::Decoder decoder;
  std::unique_ptr<draco::Mesh> mesh;
  std::string why = "no mesh";
  try {  // a hostile header can ask libdraco for more memory than there is
    auto decoded = decoder.DecodeMeshFromBuffer(&encoded);
    if (decoded.ok())
      mesh = std::move(decoded).value();
    else
      why = decoded.status().error_msg_string();
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (!mesh) fail("the Draco data in buffer view " + std::to_string(view_index) + " does not decode (" + why + ")");
  const uint32_t points = mesh->num_points(), faces = mesh->num_faces();
  if (points > kGltfMaxVertices || faces > kGltfMaxTriangles)
    fail(std::to_string(points) + " points and " + std::to_string(faces) + " triangles exceed the importer's limit");

  for (const std::string& name : attributes.Keys()) {
    const std::string aw = "attributes." + name;
    const tinygltf::Value& id = attributes.Get(name);
    const draco::PointAttribute* att =
        id.IsNumber() && index(id, uint64_t(1) << 32) >= 0 ? mesh->GetAttributeByUniqueId(uint32_t(id.GetNumberAsDouble())) : nullptr;
    if (!att) fail(aw + ": the Draco data has no attribute with that id");
    if (!att->is_mapping_identity() && att->indices_map_size() < points) fail(aw + ": the Draco attribute misses points");
    const auto named = p.attributes.find(name);
    if (named == p.attributes.end()) fail(aw + ": the primitive's own attributes have no " + name);
    if (named->second < 0 || size_t(named->second) >= m.accessors.size())
      fail(aw + ": accessor " + std::to_string(named->second) + " does not exist");
    const tinygltf::Accessor& declared = m.accessors[size_t(named->second)];
    const std::string acc = aw + " (accessor " + std::to_string(named->second) + ")";
    if (declared.count != points)
      fail(acc + ": declares " + std::to_string(declared.count) + " elements, the Draco data holds " +
           std::to_string(points) + " points");
    const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(declared.type));
    if (components <= 0 || components != att->num_components())
      fail(acc + ": " + gltf_element_type_name(declared.type) + ", the Draco attribute has " +
           std::to_string(int(att->num_components())) + " components");
    std::vector<unsigned char> data;
    bool converted = false;
    switch (declared.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: converted = attribute_values<float>(*att, points, components, data); break;
      case TINYGLTF_COMPONENT_TYPE_BYTE: converted = attribute_values<int8_t>(*att, points, components, data); break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: converted = attribute_values<uint8_t>(*att, points, components, data); break;
      case TINYGLTF_COMPONENT_TYPE_SHORT: converted = attribute_values<int16_t>(*att, points, components, data); break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: converted = attribute_values<uint16_t>(*att, points, components, data); break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: converted = attribute_values<uint32_t>(*att, points, components, data); break;
      default: fail(acc + ": component type " + gltf_component_type_name(declared.componentType) + " is not one of glTF's");
    }
    if (!converted)
      fail(acc + ": the Draco values do not convert to " + gltf_component_type_name(declared.componentType));
    named->second = add_accessor(m, declared, std::move(data), at + "." + aw + " decoded");
  }

  // Indices: the decoded faces, as 32-bit (Draco may reorder points; the file's accessor gives
  // only the count to expect).
  tinygltf::Accessor indices;
  if (p.indices >= 0) {
    if (size_t(p.indices) >= m.accessors.size()) fail("indices: accessor " + std::to_string(p.indices) + " does not exist");
    indices = m.accessors[size_t(p.indices)];
    if (indices.count != size_t(faces) * 3)
      fail("indices (accessor " + std::to_string(p.indices) + "): declares " + std::to_string(indices.count) +
           " indices, the Draco data holds " + std::to_string(faces) + " triangles");
  }
  indices.type = TINYGLTF_TYPE_SCALAR;
  indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  indices.normalized = false;
  indices.count = size_t(faces) * 3;
  std::vector<unsigned char> data(indices.count * 4);
  for (uint32_t f = 0; f < faces; ++f) {
    const draco::Mesh::Face& face = mesh->face(draco::FaceIndex(f));
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = face[k].value();
      std::memcpy(data.data() + (size_t(f) * 3 + k) * 4, &v, 4);
    }
  }
  p.indices = add_accessor(m, indices, std::move(data), at + ".indices decoded");
  p.extensions.erase(kDraco);
}

}  // namespace

void decode_draco_primitives(tinygltf::Model& m, const std::string& origin) {
  for (size_t i = 0; i < m.meshes.size(); ++i)
    for (size_t k = 0; k < m.meshes[i].primitives.size(); ++k) {
      tinygltf::Primitive& p = m.meshes[i].primitives[k];
      if (p.extensions.count(kDraco))
        decode_primitive(m, p, origin + ": meshes[" + std::to_string(i) + "].primitives[" + std::to_string(k) +
                                   "].extensions." + kDraco);
    }
}

}  // namespace weft
