#pragma once
// The ladder of docs/design.md §4 as the method registry orders it (methods::bench_ladder()): a
// method is benchmarked when the GPU runtime has it; the rest are reported as missing. `scenes` limits a method to the
// scenes it is for; `thin_reference`: measured against the reference with cloth as seed 004's
// thin layer (ReferenceRenderOptions::thin_cloth) instead of opaque cloth.
#include <set>
#include <string>
#include <vector>

namespace weft::bench {

struct LadderEntry {
  std::string name;
  std::set<std::string> scenes;  // empty: every scene
  bool thin_reference = false;
};

const std::vector<LadderEntry>& ladder();

// What a run measures: the ladder's methods the runtime has (those `requested` names, or all
// when it is empty), then any runtime method the ladder does not list; `missing`: the ladder's
// methods the runtime lacks. Throws InvalidOption for a requested name the runtime lacks.
struct LadderRun {
  std::vector<LadderEntry> run;
  std::vector<std::string> missing;
};
LadderRun select_methods(const std::vector<std::string>& available, const std::vector<std::string>& requested);

}  // namespace weft::bench
