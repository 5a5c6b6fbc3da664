#pragma once
// EXT_meshopt_compression (and KHR_meshopt_compression, the same bitstream) in glTF files:
// compressed buffer views are decoded with libmeshoptimizer before any accessor reads them (the
// fallback buffer that declares their decoded size is made loadable by gltf_loadable.h).
#include <string>

namespace tinygltf {
class Model;
}

namespace weft {

// Decodes every compressed buffer view of `model` (modes ATTRIBUTES, TRIANGLES, INDICES; filters
// OCTAHEDRAL, QUATERNION, EXPONENTIAL) into a buffer of its own and points the view there.
// Throws SceneError naming `origin`, the buffer view, the extension and the reason.
void decode_meshopt_buffer_views(tinygltf::Model& model, const std::string& origin);

}  // namespace weft
