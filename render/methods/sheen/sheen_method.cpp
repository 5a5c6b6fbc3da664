#include "methods/sheen/sheen_method.h"

#include <memory>

#include "methods/cpu_evaluation.h"
#include "methods/program_cloth.h"
#include "methods/sg_lighting_uniforms.h"
#include "methods/thread_map_textures.h"

namespace weft::gpu {

void upload_sheen(const GlProgram& program, const SheenParams& p) {
  program.use();
  const float diffuse[6] = {float(p.thread_diffuse[0].r), float(p.thread_diffuse[0].g), float(p.thread_diffuse[0].b),
                            float(p.thread_diffuse[1].r), float(p.thread_diffuse[1].g), float(p.thread_diffuse[1].b)};
  glUniform3fv(program.uniform("u_sheen_thread_diffuse"), 2, diffuse);
  glUniform3f(program.uniform("u_sheen_colour"), float(p.sheen_colour.r), float(p.sheen_colour.g),
              float(p.sheen_colour.b));
  glUniform1f(program.uniform("u_sheen_roughness"), float(p.roughness));
}

}  // namespace weft::gpu

namespace weft::methods {

namespace {
const std::vector<std::string_view> kGlsl = {"erf.glsl", "sg_lighting.glsl", "sheen.glsl"};
// The draw's parts beyond the function: a textured cloth's texels and its normal map.
std::vector<std::string_view> draw_parts() {
  std::vector<std::string_view> parts = kGlsl;
  parts.insert(parts.end(), {"thread_maps.glsl", "normal_map_frame.glsl", "cloth_normal_map.glsl"});
  return parts;
}

class SheenCloth : public gpu::ProgramCloth {
public:
  SheenCloth() : ProgramCloth(gpu::with_main(draw_parts(), "sheen.frag")) {}
  size_t add_object(size_t, const TriangleMesh& mesh, const Fabric& fabric) override {
    params_.push_back(sheen_params(fabric));
    maps_.emplace_back();
    return add_mesh(mesh);
  }
  void set_fabric(size_t handle, const Fabric& fabric) override { params_.at(handle) = sheen_params(fabric); }
  bool set_thread_maps(size_t handle, const gpu::ThreadMaps& maps) override {
    maps_.at(handle) = maps;
    return true;
  }
  bool draws_normal_maps() const override { return true; }

private:
  void upload(size_t handle, const gpu::GlProgram& program, const SgLighting& sgs) const override {
    gpu::upload_sg_lighting(program, sgs);
    gpu::upload_sheen(program, params_.at(handle));
    gpu::bind_thread_maps(program, maps_.at(handle), white_.id(), 0);
  }
  std::vector<SheenParams> params_;
  std::vector<gpu::ThreadMaps> maps_;
  gpu::WhiteTexture white_;  // thread_maps.glsl's samplers on untextured cloth
};
}  // namespace

RuntimeMethod sheen_method() {
  RuntimeMethod m;
  m.name = "sheen";
  m.glsl = kGlsl;
  m.make_gpu = [](const gpu::ClothMethodSetup&) { return std::make_unique<SheenCloth>(); };
  m.cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs,
              const TableSource& /*tables*/) {
    return CpuShade{sheen_radiance(sheen_params(b.fabric()), facing(f, wo).n, wo, sgs), 0.0};
  };
  return m;
}

}  // namespace weft::methods
