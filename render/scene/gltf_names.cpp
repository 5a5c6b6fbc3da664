#include "scene/gltf_names.h"

#include <tiny_gltf.h>

namespace weft {

std::string gltf_component_type_name(int component_type) {
  const char* name = "unknown component type";
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: name = "BYTE"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: name = "UNSIGNED_BYTE"; break;
    case TINYGLTF_COMPONENT_TYPE_SHORT: name = "SHORT"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: name = "UNSIGNED_SHORT"; break;
    case TINYGLTF_COMPONENT_TYPE_INT: name = "INT"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: name = "UNSIGNED_INT"; break;
    case TINYGLTF_COMPONENT_TYPE_FLOAT: name = "FLOAT"; break;
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: name = "DOUBLE"; break;
  }
  return std::string(name) + " (" + std::to_string(component_type) + ")";
}

std::string gltf_element_type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
  }
  return "an unknown element type (" + std::to_string(type) + ")";
}

std::string gltf_mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
  }
  return "unknown";
}

}  // namespace weft
