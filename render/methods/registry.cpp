#include "methods/registry.h"

#include <algorithm>
#include <stdexcept>

#include "methods/iwasaki/iwasaki_method.h"
#include "methods/mdfrot/mdfrot_method.h"
#include "methods/mizutani/mizutani_method.h"
#include "methods/sgpoint/sgpoint_method.h"
#include "methods/sheer/sheer_method.h"
#include "methods/sheen/sheen_method.h"
#include "methods/thin/thin_method.h"

namespace weft::methods {

const std::vector<RuntimeMethod>& registry() {
  static const std::vector<RuntimeMethod> methods = [] {
    std::vector<RuntimeMethod> m = {sgpoint_method(), sheen_method(), mdfrot_method(), thin_method(), mizutani_method()};
    for (auto& rung : iwasaki_methods()) m.push_back(std::move(rung));
    m.push_back(sheer_method());
    m.push_back(sheer_vertex_method());
    return m;
  }();
  return methods;
}

const RuntimeMethod* find_method(std::string_view name) {
  for (const auto& m : registry())
    if (m.name == name) return &m;
  return nullptr;
}

const RuntimeMethod& method(std::string_view name) {
  if (const RuntimeMethod* m = find_method(name)) return *m;
  std::string all;
  for (const auto& m : registry()) all += (all.empty() ? "" : ", ") + m.name;
  throw std::invalid_argument("unknown GPU method '" + std::string(name) + "' (available: " + all + ")");
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const auto& m : registry()) names.push_back(m.name);
  return names;
}

std::vector<BenchLadderEntry> bench_ladder() {
  std::vector<const RuntimeMethod*> sorted;
  for (const auto& m : registry()) sorted.push_back(&m);
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const RuntimeMethod* a, const RuntimeMethod* b) { return a->ladder_position < b->ladder_position; });
  std::vector<BenchLadderEntry> ladder;
  for (const RuntimeMethod* m : sorted) ladder.push_back({m->name, m->bench_scenes, m->reference == BenchReference::thin_layer});
  return ladder;
}

std::vector<const RuntimeMethod*> stability_methods() {
  std::vector<const RuntimeMethod*> out;
  for (const auto& m : registry())
    if (m.stability_position >= 0 && m.cpu) out.push_back(&m);
  std::stable_sort(out.begin(), out.end(),
                   [](const RuntimeMethod* a, const RuntimeMethod* b) { return a->stability_position < b->stability_position; });
  return out;
}

}  // namespace weft::methods
