#pragma once
// glTF's enum values in words for the importer's messages ("SHORT (5122)", "VEC3"): an author
// reads the name, the number finds it in the spec.
#include <string>

namespace weft {

std::string gltf_component_type_name(int component_type);
std::string gltf_element_type_name(int type);
std::string gltf_mode_name(int mode);  // a primitive's mode: "LINES"

}  // namespace weft
