#include "methods/iwasaki/iwasaki_method.h"

#include <memory>

#include "methods/cpu_evaluation.h"
#include "methods/iwasaki/iwasaki.h"
#include "methods/iwasaki/iwasaki_cloth.h"

namespace weft::methods {

namespace {
enum class Masks { none, open_share, broad_lobe_quadrature };

RuntimeMethod seed000_method(gpu::IwasakiCloth::Evaluation evaluation, Masks masks = Masks::none) {
  RuntimeMethod m;
  m.seed000 = Seed000Tables::required;
  m.glsl = gpu::iwasaki_glsl();
  m.make_gpu = [evaluation, masks](const gpu::ClothMethodSetup& s) {
    gpu::IwasakiShaders shaders =
        masks == Masks::broad_lobe_quadrature ? gpu::iwasaki_quadrature_shaders() : gpu::iwasaki_shaders();
    shaders.open_share_masks = masks == Masks::open_share;
    return std::make_unique<gpu::IwasakiCloth>(s.bundle, evaluation, shaders);
  };
  m.visibility_masks = masks != Masks::none;
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
  RuntimeMethod m = seed000_method(gpu::IwasakiCloth::Evaluation::per_pixel, Masks::open_share);
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
  RuntimeMethod m = seed000_method(gpu::IwasakiCloth::Evaluation::per_vertex, Masks::open_share);
  m.name = "iwasaki_vertex_mask";
  m.ladder_position = 1;
  return m;
}

RuntimeMethod iwasaki_quadrature_method() {
  RuntimeMethod m = seed000_method(gpu::IwasakiCloth::Evaluation::per_pixel, Masks::broad_lobe_quadrature);
  m.name = "iwasaki_quadrature";
  m.ladder_position = 0;
  return m;
}

RuntimeMethod iwasaki_vertex_quadrature_method() {
  RuntimeMethod m = seed000_method(gpu::IwasakiCloth::Evaluation::per_vertex, Masks::broad_lobe_quadrature);
  m.name = "iwasaki_vertex_quadrature";
  m.ladder_position = 1;
  return m;
}

}  // namespace weft::methods
