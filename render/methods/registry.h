#pragma once
// The runtime methods, one entry each (runtime_method.h). The scene renderer, `weft render`,
// `weft bench` and the parity tests all pick methods here. A new method is a folder
// render/methods/<name>/ (GLSL, C++ twin, <name>_method.{h,cpp}), one line in registry.cpp's
// list and one weft_method(...) line in render/methods/CMakeLists.txt.
#include <set>
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

// One row of the bench's speed/accuracy ladder (docs/design.md §4).
struct BenchLadderEntry {
  std::string name;
  std::set<std::string> scenes;  // empty: every scene
  bool thin_reference = false;   // measured against the thin-layer reference
};
// Every method in ladder order.
std::vector<BenchLadderEntry> bench_ladder();
// The methods with a C++ evaluation of their own, in the stability table's order.
std::vector<const RuntimeMethod*> stability_methods();

}  // namespace weft::methods
