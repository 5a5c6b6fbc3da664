#pragma once
// What tinygltf 2.7 refuses although glTF allows it, made loadable before tinygltf parses the
// file: a meshopt fallback buffer without data (EXT_meshopt_compression) and a Draco primitive's
// index accessor without a buffer view (KHR_draco_mesh_compression).
#include <string>

namespace weft {

// The file's bytes (.gltf text or .glb) with each meshopt fallback buffer given one byte of
// stand-in data (a decoder never reads it: gltf_meshopt.h refuses views into it) and each Draco
// primitive's index accessor pointed at the Draco buffer view (gltf_draco.h replaces it). `bytes`
// unchanged when there is nothing to adjust, or when they are not glTF (tinygltf says why).
std::string loadable_by_tinygltf(const std::string& bytes);

}  // namespace weft
