#include "methods/iwasaki/iwasaki_method.h"

#include <memory>

#include "methods/cpu_evaluation.h"
#include "methods/iwasaki/iwasaki.h"
#include "methods/iwasaki/iwasaki_cloth.h"

namespace weft::methods {

namespace {
const std::vector<std::string_view> kGlsl = {"microcylinder.glsl", "erf.glsl", "sg_lighting.glsl", "hemisphere_grid.glsl", "iwasaki.glsl"};

RuntimeMethod seed000_method(gpu::IwasakiCloth::Evaluation evaluation, bool open_share_masks = false) {
  RuntimeMethod m;
  m.seed000 = Seed000Tables::required;
  m.glsl = kGlsl;
  m.make_gpu = [evaluation, open_share_masks](const gpu::ClothMethodSetup& s) {
    gpu::IwasakiShaders shaders = gpu::iwasaki_shaders();
    shaders.open_share_masks = open_share_masks;
    return std::make_unique<gpu::IwasakiCloth>(s.bundle, evaluation, shaders);
  };
  m.visibility_masks = open_share_masks;
  return m;
}
}  // namespace

RuntimeMethod iwasaki_method() {
  RuntimeMethod m = seed000_method(gpu::IwasakiCloth::Evaluation::per_pixel);
  m.name = "iwasaki";
  m.ladder_position = 0;
  m.stability_position = 0;
  m.cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs,
              const TableSource& tables) {
    const TableBsdf t = stress_table_bsdf(b.fabric(), tables);
    return CpuShade{iwasaki_radiance(t.bsdf, *t.tables, facing(f, wo), wo, sgs).radiance, 0.0};
  };
  return m;
}

RuntimeMethod iwasaki_mask_method() {
  RuntimeMethod m = seed000_method(gpu::IwasakiCloth::Evaluation::per_pixel, true);
  m.name = "iwasaki_mask";
  m.ladder_position = 0;
  return m;
}

RuntimeMethod iwasaki_vertex_method() {
  RuntimeMethod m = seed000_method(gpu::IwasakiCloth::Evaluation::per_vertex);
  m.name = "iwasaki_vertex";
  m.ladder_position = 1;
  return m;
}

RuntimeMethod iwasaki_vertex_mask_method() {
  RuntimeMethod m = seed000_method(gpu::IwasakiCloth::Evaluation::per_vertex, true);
  m.name = "iwasaki_vertex_mask";
  m.ladder_position = 1;
  return m;
}

}  // namespace weft::methods
