#include "methods/mdfrot/mdfrot_method.h"

#include <memory>
#include <string>

#include "gl/gl_error.h"
#include "methods/cpu_evaluation.h"
#include "methods/program_cloth.h"
#include "methods/sg_lighting_uniforms.h"

namespace weft::gpu {

void upload_mdfrot(const GlProgram& program, const MdfrotParams& p) {
  program.use();
  std::vector<float> tilts(2 * kMdfrotMaxSamples, 0.0f);
  for (int j = 0; j < 2; ++j) {
    const MdfrotThread& t = p.threads[j];
    const int n = int(t.tilts.size());
    if (n < 1 || n > kMdfrotMaxSamples)
      throw GpuError("mdfrot: thread " + std::to_string(j + 1) + " has " + std::to_string(n) +
                     " samples; the shader takes 1.." + std::to_string(kMdfrotMaxSamples));
    const std::string s = "u_mdf_threads[" + std::to_string(j) + "].";
    glUniform3f(program.uniform((s + "diffuse").c_str()), float(t.diffuse.r), float(t.diffuse.g), float(t.diffuse.b));
    glUniform1f(program.uniform((s + "f0").c_str()), float(t.f0));
    glUniform1f(program.uniform((s + "n_along").c_str()), float(t.n_along));
    glUniform1f(program.uniform((s + "n_across").c_str()), float(t.n_across));
    glUniform1f(program.uniform((s + "weight").c_str()), float(t.weight));
    glUniform1i(program.uniform((s + "samples").c_str()), n);
    for (int k = 0; k < n; ++k) tilts[j * kMdfrotMaxSamples + k] = float(t.tilts[k]);
  }
  glUniform1fv(program.uniform("u_mdf_tilts"), 2 * kMdfrotMaxSamples, tilts.data());
  glUniform1f(program.uniform("u_mdf_bulge"), float(p.bulge));
}

}  // namespace weft::gpu

namespace weft::methods {

namespace {
const std::vector<std::string_view> kGlsl = {"erf.glsl", "sg_lighting.glsl", "mdfrot.glsl"};

class MdfrotCloth : public gpu::ProgramCloth {
public:
  MdfrotCloth() : ProgramCloth(gpu::with_main(kGlsl, "mdfrot.frag")) {}
  size_t add_object(size_t, const TriangleMesh& mesh, const Fabric& fabric) override {
    params_.push_back(mdfrot_params(fabric));
    return add_mesh(mesh);
  }
  void set_fabric(size_t handle, const Fabric& fabric) override { params_.at(handle) = mdfrot_params(fabric); }

private:
  void upload(size_t handle, const gpu::GlProgram& program, const SgLighting& sgs) const override {
    gpu::upload_sg_lighting(program, sgs);
    gpu::upload_mdfrot(program, params_.at(handle));
  }
  std::vector<MdfrotParams> params_;
};
}  // namespace

RuntimeMethod mdfrot_method() {
  RuntimeMethod m;
  m.name = "mdfrot";
  m.glsl = kGlsl;
  m.make_gpu = [](const gpu::ClothMethodSetup&) { return std::make_unique<MdfrotCloth>(); };
  m.cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs,
              const TableSource& /*tables*/) {
    return CpuShade{mdfrot_radiance(mdfrot_params(b.fabric()), facing(f, wo), wo, sgs), 0.0};
  };
  return m;
}

}  // namespace weft::methods
