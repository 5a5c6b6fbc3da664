#include "methods/sheer/sheer_method.h"

#include <memory>

#include "methods/cpu_evaluation.h"
#include "methods/iwasaki/iwasaki_cloth.h"
#include "methods/sheer/sheer.h"
#include "methods/thin/thin_method.h"

namespace weft::methods {

namespace {
// iwasaki's parts, then the layer's.
std::vector<std::string_view> sheer_glsl() {
  std::vector<std::string_view> parts = gpu::iwasaki_glsl();
  parts.insert(parts.end(), {"thin.glsl", "sheer.glsl"});
  return parts;
}

std::vector<std::string_view> with(std::string_view main) {
  std::vector<std::string_view> parts = sheer_glsl();
  parts.push_back(main);
  return parts;
}

gpu::IwasakiShaders sheer_shaders() {
  gpu::IwasakiShaders s;
  s.pixel_vs = {"iwasaki.vert"};
  s.pixel_fs = with("sheer.frag");
  s.pass_fs = with("vertex_pass.glsl");
  s.pass_fs.push_back("sheer_vertex_pass.frag");
  s.vertex_vs = {"sheer_vertex.vert"};
  s.vertex_fs = {"sheer_vertex.frag"};
  s.sdf_above_horizon = false;  // sheer_sdf_share reads d at the SG axes
  // sg_lighting.glsl's sharpnesses (the layer's irradiance) and the layer's τ and A.
  s.upload = [](const gpu::GlProgram& program, const Fabric& fabric, const SgLighting& drawn) {
    std::vector<float> sharpness;
    for (const auto& g : drawn) sharpness.push_back(float(g.sharpness));
    if (!sharpness.empty()) glUniform1fv(program.uniform("u_sg_sharpness"), GLsizei(sharpness.size()), sharpness.data());
    gpu::upload_thin(program, thin_params(fabric));
  };
  return s;
}

RuntimeMethod sheer_entry(gpu::IwasakiCloth::Evaluation evaluation) {
  RuntimeMethod m;
  m.see_through = true;
  m.weighting_tables = WeightingTablesUse::required;
  m.baked_visibility = true;
  m.shading = evaluation == gpu::IwasakiCloth::Evaluation::per_vertex ? Shading::per_vertex : Shading::per_pixel;
  m.glsl = sheer_glsl();
  m.make_gpu = [evaluation](const gpu::ClothMethodSetup& s) {
    return std::make_unique<gpu::IwasakiCloth>(s.bundle, evaluation, sheer_shaders());
  };
  return m;
}
}  // namespace

RuntimeMethod sheer_method() {
  RuntimeMethod m = sheer_entry(gpu::IwasakiCloth::Evaluation::per_pixel);
  m.name = "sheer";
  m.cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs,
              const TableSource& tables) {
    const TableBsdf t = stress_table_bsdf(b.fabric(), tables);
    const ThinShade s = sheer_radiance(t.bsdf, *t.tables, thin_params(b.fabric()), f, wo, sgs);
    return CpuShade{s.source, s.alpha};
  };
  return m;
}

RuntimeMethod sheer_vertex_method() {
  RuntimeMethod m = sheer_entry(gpu::IwasakiCloth::Evaluation::per_vertex);
  m.name = "sheer_vertex";
  m.kiosk_rung = true;
  return m;
}

}  // namespace weft::methods
