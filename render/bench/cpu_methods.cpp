#include "bench/cpu_methods.h"

#include <algorithm>

#include "bake/tables/table_baker.h"
#include "methods/registry.h"

namespace weft::bench {

const std::vector<CpuMethod>& cpu_methods() {
  static const std::vector<CpuMethod> methods = [] {
    std::vector<const methods::RuntimeMethod*> rows;
    for (const char* name : kStabilityOrder)
      if (const methods::RuntimeMethod* m = methods::find_method(name); m && m->cpu) rows.push_back(m);
    for (const auto& m : methods::registry())
      if (m.cpu && std::find(rows.begin(), rows.end(), &m) == rows.end()) rows.push_back(&m);
    std::vector<CpuMethod> out;
    for (const methods::RuntimeMethod* m : rows)
      out.push_back({m->name, [cpu = m->cpu, tables = table_baker()](const ClothBsdf& bsdf, const SurfaceFrame& frame,
                                                                      const dvec3& wo, std::span<const SphericalGaussian> sgs) {
                       return cpu(bsdf, frame, wo, sgs, tables);
                     }});
    return out;
  }();
  return methods;
}

}  // namespace weft::bench
