#pragma once
// KHR_draco_mesh_compression in glTF files: primitives whose geometry is a Draco bitstream are
// decoded with libdraco before the importer reads them.
#include <string>

namespace tinygltf {
class Model;
}

namespace weft {

// Decodes every Draco-compressed primitive of `model`: the attributes its extension names and its
// indices get new accessors over buffers of their own, in the component types the file's
// accessors declare, so that the primitive then reads like an uncompressed one. Throws SceneError
// naming `origin`, the mesh and primitive, the extension and the reason.
void decode_draco_primitives(tinygltf::Model& model, const std::string& origin);

}  // namespace weft
