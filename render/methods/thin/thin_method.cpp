#include "methods/thin/thin_method.h"

#include <memory>

#include "methods/fabric_uniforms.h"
#include "methods/program_cloth.h"
#include "methods/sg_lighting_uniforms.h"

namespace weft::gpu {

void upload_thin(const GlProgram& program, const ThinParams& p) {
  program.use();
  glUniform1f(program.uniform("u_thin_tau"), float(p.tau));
  glUniform3f(program.uniform("u_thin_albedo"), float(p.albedo.r), float(p.albedo.g), float(p.albedo.b));
}

}  // namespace weft::gpu

namespace weft::methods {

namespace {
const std::vector<std::string_view> kGlsl = {"microcylinder.glsl", "erf.glsl", "sg_lighting.glsl",
                                             "thin_over_sgpoint.glsl", "thin.glsl"};

class ThinCloth : public gpu::ProgramCloth {
public:
  explicit ThinCloth(int tangent_samples) : ProgramCloth(gpu::with_main(kGlsl, "thin.frag")), samples_(tangent_samples) {}
  size_t add_object(size_t, const TriangleMesh& mesh, const Fabric& fabric) override {
    objects_.emplace_back();
    set_fabric(objects_.size() - 1, fabric);
    return add_mesh(mesh);
  }
  void set_fabric(size_t handle, const Fabric& fabric) override {
    Object& o = objects_.at(handle);
    o.bsdf = std::make_unique<ClothBsdf>(fabric, samples_);
    o.thin = thin_params(fabric);
  }

private:
  struct Object {
    std::unique_ptr<ClothBsdf> bsdf;
    ThinParams thin;
  };
  void upload(size_t handle, const gpu::GlProgram& program, const SgLighting& sgs) const override {
    const Object& o = objects_.at(handle);
    gpu::upload_fabric(program, *o.bsdf);
    gpu::upload_sg_lighting(program, sgs);
    gpu::upload_thin(program, o.thin);
  }
  int samples_;
  std::vector<Object> objects_;
};
}  // namespace

RuntimeMethod thin_method() {
  RuntimeMethod m;
  m.name = "thin";
  m.see_through = true;
  m.glsl = kGlsl;
  m.make_gpu = [](const gpu::ClothMethodSetup& s) { return std::make_unique<ThinCloth>(s.tangent_samples); };
  m.cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs,
              const TableSource& /*tables*/) {
    const ThinShade s = thin_radiance(b, thin_params(b.fabric()), f, wo, sgs);
    return CpuShade{s.source, s.alpha};
  };
  return m;
}

}  // namespace weft::methods
