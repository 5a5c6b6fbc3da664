#include "methods/iwasaki/iwasaki_method.h"

#include <memory>

#include "methods/cpu_evaluation.h"
#include "methods/iwasaki/iwasaki.h"
#include "methods/iwasaki/iwasaki_cloth.h"

namespace weft::methods {

namespace {
// What a rung reads from the bundle's visibility masks (iwasaki_method.h), and its name's suffix.
struct Rung {
  const char* suffix;
  MaskUse masks;
};
constexpr Rung kRungs[] = {{"", {}},
                           {"_mask", {.open_share = true}},
                           {"_quadrature", {.broad_lobes = true}},
                           {"_mask_quadrature", {.open_share = true, .broad_lobes = true}}};

RuntimeMethod weighting_table_rung(gpu::IwasakiCloth::Evaluation evaluation, Rung rung) {
  const bool per_vertex = evaluation == gpu::IwasakiCloth::Evaluation::per_vertex;
  const MaskUse masks = rung.masks;
  RuntimeMethod m;
  m.name = std::string(per_vertex ? "iwasaki_vertex" : "iwasaki") + rung.suffix;
  m.weighting_tables = WeightingTablesUse::required;
  m.baked_visibility = true;
  m.shading = per_vertex ? Shading::per_vertex : Shading::per_pixel;
  m.masks = masks;
  m.kiosk_rung = true;
  m.glsl = gpu::iwasaki_glsl();
  m.make_gpu = [evaluation, masks](const gpu::ClothMethodSetup& s) {
    gpu::IwasakiShaders shaders = masks.broad_lobes ? gpu::iwasaki_quadrature_shaders() : gpu::iwasaki_shaders();
    shaders.open_share_masks = masks.open_share;
    return std::make_unique<gpu::IwasakiCloth>(s.bundle, evaluation, shaders);
  };
  return m;
}
}  // namespace

std::vector<RuntimeMethod> iwasaki_methods() {
  std::vector<RuntimeMethod> out;
  for (const auto evaluation : {gpu::IwasakiCloth::Evaluation::per_pixel, gpu::IwasakiCloth::Evaluation::per_vertex})
    for (const Rung& rung : kRungs) out.push_back(weighting_table_rung(evaluation, rung));
  // iwasaki's C++ evaluation (without visibility) stands for the family in the stability table.
  out.front().cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                       const TableSource& tables) {
    const TableBsdf t = stress_table_bsdf(b.fabric(), tables);
    return CpuShade{iwasaki_radiance(t.bsdf, *t.tables, facing(f, wo), wo, sgs).radiance, 0.0};
  };
  return out;
}

}  // namespace weft::methods
