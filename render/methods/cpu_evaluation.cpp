#include "methods/cpu_evaluation.h"

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <stdexcept>

#include "runtime/paper_tangent_samples.h"

namespace weft::methods {

SurfaceFrame facing(SurfaceFrame f, const dvec3& wo) {
  if (glm::dot(f.n, wo) < 0.0) {
    f.n = -f.n;
    f.v = glm::cross(f.n, f.u);
  }
  return f;
}

TableBsdf stress_table_bsdf(const Fabric& fabric, const TableSource& tables) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<WeightingTables>> cache;
  const std::scoped_lock lock(mutex);
  auto& t = cache[fabric.name];
  if (!t) {
    if (!tables) throw std::runtime_error("no table source for the C++ evaluation of fabric '" + fabric.name + "'");
    t = std::make_unique<WeightingTables>(tables.weighting(fabric, paper_tangent_samples(fabric), kStressTableGrid));
  }
  return {t.get(), ClothBsdf(fabric, t->tangent_samples)};
}

const AzimuthalTable& stress_azimuthal_table(const TableSource& tables) {
  if (!tables) throw std::runtime_error("no table source for the azimuthal table");
  static const AzimuthalTable table = tables.azimuthal();
  return table;
}

}  // namespace weft::methods
