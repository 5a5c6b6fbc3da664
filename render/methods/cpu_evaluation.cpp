#include "methods/cpu_evaluation.h"

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "bake/bake_selection.h"
#include "bake/weighting_bake.h"

namespace weft::methods {

SurfaceFrame facing(SurfaceFrame f, const dvec3& wo) {
  if (glm::dot(f.n, wo) < 0.0) {
    f.n = -f.n;
    f.v = glm::cross(f.n, f.u);
  }
  return f;
}

TableBsdf stress_table_bsdf(const Fabric& fabric) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<WeightingTables>> cache;
  const std::scoped_lock lock(mutex);
  auto& t = cache[fabric.name];
  if (!t) {
    BakeSettings s;
    s.tangent_samples = paper_tangent_samples(fabric);
    s.xi_resolution = s.wo_resolution = s.wi_resolution = kStressTableGrid;
    t = std::make_unique<WeightingTables>(bake_weighting_tables(fabric, s));
  }
  return {t.get(), ClothBsdf(fabric, t->tangent_samples)};
}

const AzimuthalTable& stress_azimuthal_table() {
  static const AzimuthalTable table = bake_azimuthal_table();
  return table;
}

}  // namespace weft::methods
