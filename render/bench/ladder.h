#pragma once
// The ladder of docs/design.md §4: the bench's rows, one per runtime method, in the registry's
// order (methods/registry.h). A see-through method is measured on the bench's see-through scene
// alone, against the reference with cloth as a thin layer (ReferenceRenderOptions::thin_cloth);
// every other method on every scene against the opaque reference. select_methods keeps the
// ladder's rows a runtime has, then runs any method it has that the ladder lacks.
#include <set>
#include <string>
#include <vector>

namespace weft::bench {

inline constexpr const char* kSeeThroughScene = "curtain";  // the bench's sheer before a window

struct LadderEntry {
  std::string name;
  std::set<std::string> scenes;  // empty: every scene
  bool thin_reference = false;
};

// In the chart's and the report's order.
const std::vector<LadderEntry>& ladder();
// Whether the method named `name` is measured against the thin-layer reference (thin, sheer, sheer_vertex).
bool thin_reference(const std::string& name);

// What a run measures: the ladder's methods the runtime has (those `requested` names, or all
// when it is empty), then any runtime method the ladder does not list; `missing`: the ladder's
// methods the runtime lacks. Throws InvalidOption for a requested name the runtime lacks.
struct LadderRun {
  std::vector<LadderEntry> run;
  std::vector<std::string> missing;
};
LadderRun select_methods(const std::vector<std::string>& available, const std::vector<std::string>& requested);

}  // namespace weft::bench
