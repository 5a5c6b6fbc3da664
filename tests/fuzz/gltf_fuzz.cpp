// libFuzzer target for glTF files (.gltf text or .glb): any bytes either import into a scene
// that keeps the importer's promises (finite positions, unit normals, unit warps ⟂ normals,
// indices in range) or raise a SceneError; nothing else may escape, crash or read out of bounds.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/gltf_scene.h"

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  weft::GltfImportOptions options;
  options.fallback_fabric = "linen_plain";  // every material cloth: the warp paths run too
  try {
    // External buffers resolve against a directory that does not exist.
    const weft::Scene s = weft::parse_gltf_scene(bytes, "fuzz.gltf", "/nonexistent-weft-fuzz", options);
    if (s.objects.empty()) __builtin_trap();
    for (const auto& o : s.objects) {
      const auto& m = o.mesh;
      if (m.normals.size() != m.positions.size() || m.warps.size() != m.positions.size()) __builtin_trap();
      for (size_t v = 0; v < m.positions.size(); ++v) {
        if (!finite(m.positions[v])) __builtin_trap();
        if (std::abs(glm::length(m.normals[v]) - 1.0) > 1e-6) __builtin_trap();
        if (std::abs(glm::length(m.warps[v]) - 1.0) > 1e-6) __builtin_trap();
        if (std::abs(glm::dot(m.normals[v], m.warps[v])) > 1e-6) __builtin_trap();
      }
      for (const auto& t : m.triangles)
        for (uint32_t i : t)
          if (i >= m.positions.size()) __builtin_trap();
    }
  } catch (const weft::SceneError&) {
    // The expected outcome for almost every input.
  }
  return 0;
}
