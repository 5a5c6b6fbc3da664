#pragma once
// The runtime methods, one entry each (runtime_method.h), and the one API over them: the scene
// renderer, the kiosk, `weft render`, `weft bench` and the parity tests all pick methods here.
// A new method is a folder render/methods/<name>/ (GLSL, C++ twin, <name>_method.{h,cpp}), one
// line in registry.cpp's list and one weft_method(...) line in render/methods/CMakeLists.txt;
// its traits (runtime_method.h) tell the kiosk and the commands what it needs.
#include <string>
#include <string_view>
#include <vector>

#include "methods/runtime_method.h"

namespace weft::methods {

// Every method, in the order listings and error messages name them.
const std::vector<RuntimeMethod>& registry();
// The method named `name`; null if there is none.
const RuntimeMethod* find_method(std::string_view name);
// The same; throws std::invalid_argument "unknown GPU method 'NAME' (available: a, b, ...)".
const RuntimeMethod& method(std::string_view name);
std::vector<std::string> method_names();

}  // namespace weft::methods
