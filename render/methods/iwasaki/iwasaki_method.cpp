#include "methods/iwasaki/iwasaki_method.h"

#include <memory>

#include "methods/cpu_evaluation.h"
#include "methods/iwasaki/iwasaki.h"
#include "methods/iwasaki/iwasaki_cloth.h"

namespace weft::methods {

namespace {
// What a rung reads from the bundle's visibility masks (iwasaki_method.h).
struct MaskUse {
  const char* suffix;
  bool open_share, quadrature;
};
constexpr MaskUse kMaskUses[] = {
    {"", false, false}, {"_mask", true, false}, {"_quadrature", false, true}, {"_mask_quadrature", true, true}};

RuntimeMethod seed000_method(gpu::IwasakiCloth::Evaluation evaluation, MaskUse masks) {
  const bool per_vertex = evaluation == gpu::IwasakiCloth::Evaluation::per_vertex;
  RuntimeMethod m;
  m.name = std::string(per_vertex ? "iwasaki_vertex" : "iwasaki") + masks.suffix;
  m.ladder_position = per_vertex ? 1 : 0;
  m.seed000 = Seed000Tables::required;
  m.glsl = gpu::iwasaki_glsl();
  m.make_gpu = [evaluation, masks](const gpu::ClothMethodSetup& s) {
    gpu::IwasakiShaders shaders = masks.quadrature ? gpu::iwasaki_quadrature_shaders() : gpu::iwasaki_shaders();
    shaders.open_share_masks = masks.open_share;
    return std::make_unique<gpu::IwasakiCloth>(s.bundle, evaluation, shaders);
  };
  m.visibility_masks = masks.open_share || masks.quadrature;
  return m;
}
}  // namespace

std::vector<RuntimeMethod> iwasaki_methods() {
  std::vector<RuntimeMethod> out;
  for (const auto evaluation : {gpu::IwasakiCloth::Evaluation::per_pixel, gpu::IwasakiCloth::Evaluation::per_vertex})
    for (const MaskUse& masks : kMaskUses) out.push_back(seed000_method(evaluation, masks));
  // iwasaki's C++ evaluation (without visibility) stands for the family in the stability table.
  out.front().stability_position = 0;
  out.front().cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                       const TableSource& tables) {
    const TableBsdf t = stress_table_bsdf(b.fabric(), tables);
    return CpuShade{iwasaki_radiance(t.bsdf, *t.tables, facing(f, wo), wo, sgs).radiance, 0.0};
  };
  return out;
}

}  // namespace weft::methods
