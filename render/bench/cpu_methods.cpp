#include "bench/cpu_methods.h"

#include <map>
#include <memory>
#include <mutex>

#include "bake/azimuthal_bake.h"
#include "bake/bake_selection.h"
#include "bake/weighting_bake.h"
#include "methods/iwasaki.h"
#include "methods/mdfrot.h"
#include "methods/mizutani.h"
#include "methods/sgpoint.h"
#include "methods/sheen.h"
#include "methods/thin.h"

namespace weft::bench {

namespace {
// The GPU shades the side facing the eye; so do these.
SurfaceFrame facing(SurfaceFrame f, const dvec3& wo) {
  if (glm::dot(f.n, wo) < 0.0) {
    f.n = -f.n;
    f.v = glm::cross(f.n, f.u);
  }
  return f;
}
// Tables for a stress fabric, baked once per preset name (they depend on the thread curves,
// not on A or γ, which the γ_s = 1° case changes), and the matching BSDF (the tables' tangent
// samples, the case's thread parameters).
struct TableBsdf {
  const WeightingTables* tables;
  ClothBsdf bsdf;
};
TableBsdf table_bsdf(const Fabric& fabric) {
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
const AzimuthalTable& azimuthal() {
  static const AzimuthalTable table = bake_azimuthal_table();
  return table;
}
}  // namespace

const std::vector<CpuMethod>& cpu_methods() {
  static const std::vector<CpuMethod> methods = {
      {"iwasaki",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         const TableBsdf t = table_bsdf(b.fabric());
         return CpuShade{iwasaki_radiance(t.bsdf, *t.tables, facing(f, wo), wo, sgs).radiance, 0.0};
       }},
      {"mizutani",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         const TableBsdf t = table_bsdf(b.fabric());
         return CpuShade{mizutani_radiance(t.bsdf, *t.tables, azimuthal(), facing(f, wo), wo, sgs).radiance, 0.0};
       }},
      {"sgpoint",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         return CpuShade{sgpoint_radiance(b, facing(f, wo), wo, sgs), 0.0};
       }},
      {"sheen",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         return CpuShade{sheen_radiance(sheen_params(b.fabric()), facing(f, wo).n, wo, sgs), 0.0};
       }},
      {"mdfrot",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         return CpuShade{mdfrot_radiance(mdfrot_params(b.fabric()), facing(f, wo), wo, sgs), 0.0};
       }},
      {"thin",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         const ThinShade s = thin_radiance(b, thin_params(b.fabric()), f, wo, sgs);
         return CpuShade{s.source, s.alpha};
       }},
  };
  return methods;
}

}  // namespace weft::bench
