#include "methods/sheen/sheen_method.h"

#include <memory>

#include "methods/cpu_evaluation.h"
#include "methods/program_cloth.h"
#include "methods/sg_lighting_uniforms.h"

namespace weft::gpu {

void upload_sheen(const GlProgram& program, const SheenParams& p) {
  program.use();
  glUniform3f(program.uniform("u_sheen_diffuse"), float(p.diffuse.r), float(p.diffuse.g), float(p.diffuse.b));
  glUniform3f(program.uniform("u_sheen_colour"), float(p.sheen_colour.r), float(p.sheen_colour.g),
              float(p.sheen_colour.b));
  glUniform1f(program.uniform("u_sheen_roughness"), float(p.roughness));
}

}  // namespace weft::gpu

namespace weft::methods {

namespace {
const std::vector<std::string_view> kGlsl = {"erf.glsl", "sg_lighting.glsl", "sheen.glsl"};

class SheenCloth : public gpu::ProgramCloth {
public:
  SheenCloth() : ProgramCloth(gpu::with_main(kGlsl, "sheen.frag")) {}
  size_t add_object(size_t, const TriangleMesh& mesh, const Fabric& fabric) override {
    params_.push_back(sheen_params(fabric));
    return add_mesh(mesh);
  }
  void set_fabric(size_t handle, const Fabric& fabric) override { params_.at(handle) = sheen_params(fabric); }

private:
  void upload(size_t handle, const gpu::GlProgram& program, const SgLighting& sgs) const override {
    gpu::upload_sg_lighting(program, sgs);
    gpu::upload_sheen(program, params_.at(handle));
  }
  std::vector<SheenParams> params_;
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
