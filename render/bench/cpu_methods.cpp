#include "bench/cpu_methods.h"

#include "methods/registry.h"

namespace weft::bench {

const std::vector<CpuMethod>& cpu_methods() {
  static const std::vector<CpuMethod> methods = [] {
    std::vector<CpuMethod> out;
    for (const methods::RuntimeMethod* m : methods::stability_methods()) out.push_back({m->name, m->cpu});
    return out;
  }();
  return methods;
}

}  // namespace weft::bench
