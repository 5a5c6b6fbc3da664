#include "scene/gltf_meshopt.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include "scene/gltf_scene.h"
#include "scene/scene.h"

namespace weft {

namespace {

constexpr const char* kExtensions[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};

}  // namespace

void decode_meshopt_buffer_views(tinygltf::Model& m, const std::string& origin) {
  std::vector<bool> fallback(m.buffers.size(), false);
  for (size_t i = 0; i < m.buffers.size(); ++i)
    for (const char* name : kExtensions)
      if (const auto it = m.buffers[i].extensions.find(name); it != m.buffers[i].extensions.end())
        fallback[i] = it->second.IsObject() && it->second.Get("fallback").IsBool() && it->second.Get("fallback").Get<bool>();

  size_t decoded_total = 0;
  for (size_t i = 0; i < m.bufferViews.size(); ++i) {
    tinygltf::BufferView& view = m.bufferViews[i];
    const char* name = nullptr;
    for (const char* n : kExtensions)
      if (!name && view.extensions.count(n)) name = n;
    const std::string at = "bufferViews[" + std::to_string(i) + "]";
    auto fail = [&](const std::string& why) {
      throw SceneError(origin + ": " + at + (name ? std::string(".extensions.") + name : std::string()) + ": " + why);
    };
    if (!name) {
      if (view.buffer >= 0 && size_t(view.buffer) < fallback.size() && fallback[size_t(view.buffer)])
        fail("points into buffer " + std::to_string(view.buffer) +
             ", a meshopt fallback that holds no data, and is not compressed itself");
      continue;
    }
    const tinygltf::Value& ext = view.extensions.at(name);
    if (!ext.IsObject()) fail("expected an object");
    // A whole number ≥ 0 from the extension; `fallback_value` when absent and optional (≥ 0).
    auto number = [&](const char* key, double fallback_value = -1.0) -> size_t {
      if (!ext.Has(key)) {
        if (fallback_value < 0.0) fail(std::string("has no ") + key);
        return size_t(fallback_value);
      }
      const tinygltf::Value& v = ext.Get(key);
      const double x = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
      if (!(x >= 0.0 && x <= 9007199254740992.0 && x == std::floor(x))) fail(std::string(key) + ": expected a whole number ≥ 0");
      return size_t(x);
    };
    auto text = [&](const char* key, const char* fallback_value) -> std::string {
      if (!ext.Has(key)) {
        if (!fallback_value) fail(std::string("has no ") + key);
        return fallback_value;
      }
      if (!ext.Get(key).IsString()) fail(std::string(key) + ": expected a string");
      return ext.Get(key).Get<std::string>();
    };
    const size_t buffer = number("buffer"), offset = number("byteOffset", 0), length = number("byteLength"),
                 stride = number("byteStride"), count = number("count");
    const std::string mode = text("mode", nullptr), filter = text("filter", "NONE");
    if (buffer >= m.buffers.size()) fail("buffer " + std::to_string(buffer) + " does not exist");
    const auto& source = m.buffers[buffer].data;
    if (offset > source.size() || length > source.size() - offset)
      fail("bytes " + std::to_string(offset) + " + " + std::to_string(length) + " run past the end of buffer " +
           std::to_string(buffer) + " (" + std::to_string(source.size()) + " bytes)");
    if (count == 0) fail("count is 0");
    if (count > std::max(kGltfMaxVertices, 3 * kGltfMaxTriangles))
      fail(std::to_string(count) + " elements exceed the importer's limit");
    // The decoders take these as given (assertions, not checks): every combination is checked first.
    if (mode == "ATTRIBUTES") {
      if (stride == 0 || stride > 256 || stride % 4 != 0)
        fail("byteStride " + std::to_string(stride) + " for ATTRIBUTES: must be a multiple of 4 up to 256");
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
      if (stride != 2 && stride != 4) fail("byteStride " + std::to_string(stride) + " for " + mode + ": must be 2 or 4");
      if (mode == "TRIANGLES" && count % 3 != 0) fail("count " + std::to_string(count) + " for TRIANGLES: not whole triangles");
    } else {
      fail("mode '" + mode + "': expected ATTRIBUTES, TRIANGLES or INDICES");
    }
    if (filter != "NONE") {
      if (mode != "ATTRIBUTES") fail("filter " + filter + " on " + mode + ": filters apply to ATTRIBUTES only");
      if (filter == "OCTAHEDRAL" && stride != 4 && stride != 8)
        fail("byteStride " + std::to_string(stride) + " for filter OCTAHEDRAL: must be 4 or 8");
      else if (filter == "QUATERNION" && stride != 8)
        fail("byteStride " + std::to_string(stride) + " for filter QUATERNION: must be 8");
      else if (filter != "OCTAHEDRAL" && filter != "QUATERNION" && filter != "EXPONENTIAL")
        fail("filter '" + filter + "': expected NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
    }
    const size_t size = count * stride;
    if (view.byteLength != size)
      fail("decodes to count × byteStride = " + std::to_string(size) + " bytes, but the buffer view's byteLength is " +
           std::to_string(view.byteLength));
    if (size > kGltfMaxFileBytes - decoded_total) fail("the decoded views exceed the importer's size limit");
    decoded_total += size;

    std::vector<unsigned char> out(size);
    const unsigned char* encoded = source.data() + offset;
    int rc = 0;
    if (mode == "ATTRIBUTES")
      rc = meshopt_decodeVertexBuffer(out.data(), count, stride, encoded, length);
    else if (mode == "TRIANGLES")
      rc = meshopt_decodeIndexBuffer(out.data(), count, stride, encoded, length);
    else
      rc = meshopt_decodeIndexSequence(out.data(), count, stride, encoded, length);
    if (rc != 0)
      fail("the " + mode + " data does not decode (meshoptimizer error " + std::to_string(rc) +
           "): truncated, or not encoded with this byteStride and count");
    if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), count, stride);
    if (filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), count, stride);
    if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), count, stride);

    tinygltf::Buffer decoded;
    decoded.name = at + " decoded";
    decoded.data = std::move(out);
    m.buffers.push_back(std::move(decoded));
    fallback.push_back(false);
    view.buffer = static_cast<int>(m.buffers.size() - 1);
    view.byteOffset = 0;
    view.extensions.erase(name);
  }
}

}  // namespace weft
