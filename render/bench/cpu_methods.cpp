#include "bench/cpu_methods.h"

#include "bake/tables/table_baker.h"
#include "methods/registry.h"

namespace weft::bench {

const std::vector<CpuMethod>& cpu_methods() {
  static const std::vector<CpuMethod> methods = [] {
    std::vector<CpuMethod> out;
    for (const methods::RuntimeMethod* m : methods::stability_methods())
      out.push_back({m->name, [cpu = m->cpu, tables = table_baker()](const ClothBsdf& bsdf, const SurfaceFrame& frame,
                                                                      const dvec3& wo, std::span<const SphericalGaussian> sgs) {
                       return cpu(bsdf, frame, wo, sgs, tables);
                     }});
    return out;
  }();
  return methods;
}

}  // namespace weft::bench
