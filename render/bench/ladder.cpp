#include "bench/ladder.h"

#include <algorithm>

#include "bench/bench_options.h"
#include "methods/registry.h"

namespace weft::bench {

const std::vector<LadderEntry>& ladder() {
  static const std::vector<LadderEntry> l = [] {
    std::vector<LadderEntry> out;
    for (const methods::RuntimeMethod& m : methods::registry())
      out.push_back(m.see_through ? LadderEntry{m.name, {std::string(kSeeThroughScene)}, true} : LadderEntry{m.name, {}, false});
    return out;
  }();
  return l;
}

bool thin_reference(const std::string& name) {
  for (const auto& e : ladder())
    if (e.name == name) return e.thin_reference;
  return false;
}

LadderRun select_methods(const std::vector<std::string>& available, const std::vector<std::string>& requested) {
  LadderRun r;
  for (const auto& m : requested) {
    bool ok = false;
    for (const auto& n : available) ok = ok || n == m;
    if (!ok) throw InvalidOption("--methods: '" + m + "' is not a GPU method here");
  }
  auto wanted = [&](const std::string& n) {
    return requested.empty() || std::find(requested.begin(), requested.end(), n) != requested.end();
  };
  for (const auto& e : ladder()) {
    if (std::find(available.begin(), available.end(), e.name) == available.end()) {
      r.missing.push_back(e.name);
      continue;
    }
    if (wanted(e.name)) r.run.push_back(e);
  }
  for (const auto& n : available) {  // a GPU method the ladder does not list still runs
    bool listed = false;
    for (const auto& e : ladder()) listed = listed || e.name == n;
    if (!listed && wanted(n)) r.run.push_back({n, {}, false});
  }
  return r;
}

}  // namespace weft::bench
