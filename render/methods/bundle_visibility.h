#pragma once
// The bundle's visibility of one scene object, checked before a GPU side reads it: iwasaki's
// cloth (iwasaki_cloth.h) and the scene renderer's floors and occluders both take theirs here.
#include "runtime/shading_data.h"
#include "scene/mesh.h"

namespace weft::gpu {

// The visibility of scene object `scene_index` (null: unoccluded), checked against the mesh it
// was baked for (vertex count, per-vertex frames) and the κ table it needs; throws GpuError
// naming the object.
const ObjectVisibility* checked_visibility(const ShadingData& data, size_t scene_index, const TriangleMesh& mesh);

}  // namespace weft::gpu
