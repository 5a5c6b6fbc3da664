#pragma once
// The GLSL sources in render/shaders/ and render/methods/<name>/, compiled into the binary.
#include <string>
#include <string_view>

namespace weft::shaders {
// The text of `name` (e.g. "microcylinder.glsl"); throws std::out_of_range if unknown.
std::string_view source(std::string_view name);
}  // namespace weft::shaders
