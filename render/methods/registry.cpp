#include "methods/registry.h"

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
    // In the bench's chart and report order (bench/ladder.h): the weighting-table family first.
    std::vector<RuntimeMethod> m = iwasaki_methods();
    for (RuntimeMethod r : {mizutani_method(), sgpoint_method(), mdfrot_method(), sheen_method(), thin_method(), sheer_method(),
                            sheer_vertex_method()})
      m.push_back(std::move(r));
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

}  // namespace weft::methods
