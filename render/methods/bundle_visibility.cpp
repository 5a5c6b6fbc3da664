#include "methods/bundle_visibility.h"

#include <string>

#include "gl/gl_error.h"

namespace weft::gpu {

const ObjectVisibility* checked_visibility(const ShadingData& data, size_t scene_index, const TriangleMesh& mesh) {
  const auto found = data.visibility.find(scene_index);
  if (found == data.visibility.end()) return nullptr;
  const ObjectVisibility& vis = found->second;
  const std::string object = "the visibility of object " + std::to_string(scene_index);
  if (vis.vertex_count() != mesh.positions.size())
    throw GpuError(object + " has " + std::to_string(vis.vertex_count()) + " vertices, the mesh " +
                   std::to_string(mesh.positions.size()));
  if (mesh.warps.size() != mesh.positions.size()) throw GpuError(object + ": its mesh has no per-vertex frames (warps)");
  if (!data.kappa) throw GpuError(object + " comes without a kappa table");
  return &vis;
}

}  // namespace weft::gpu
