#include "methods/sgpoint/sgpoint_method.h"

#include <memory>

#include "methods/cpu_evaluation.h"
#include "methods/fabric_uniforms.h"
#include "methods/program_cloth.h"
#include "methods/sgpoint/sgpoint.h"

namespace weft::methods {

namespace {
const std::vector<std::string_view> kGlsl = {"microcylinder.glsl"};

class SgpointCloth : public gpu::ProgramCloth {
public:
  explicit SgpointCloth(int tangent_samples) : ProgramCloth(gpu::with_main(kGlsl, "sgpoint.frag")), samples_(tangent_samples) {}
  size_t add_object(size_t, const TriangleMesh& mesh, const Fabric& fabric) override {
    bsdfs_.push_back(nullptr);
    set_fabric(bsdfs_.size() - 1, fabric);
    return add_mesh(mesh);
  }
  void set_fabric(size_t handle, const Fabric& fabric) override {
    bsdfs_.at(handle) = std::make_unique<ClothBsdf>(fabric, samples_);
  }

private:
  void upload(size_t handle, const gpu::GlProgram& program, const SgLighting& sgs) const override {
    std::vector<float> axes, powers;
    for (const auto& g : sgs) {
      const glm::dvec3 p = integral(g);  // all of the SG's power along its axis
      axes.insert(axes.end(), {float(g.axis.x), float(g.axis.y), float(g.axis.z)});
      powers.insert(powers.end(), {float(p.r), float(p.g), float(p.b)});
    }
    gpu::upload_fabric(program, *bsdfs_.at(handle));
    glUniform1i(program.uniform("u_sg_count"), int(sgs.size()));
    if (!sgs.empty()) {
      glUniform3fv(program.uniform("u_sg_axis"), GLsizei(sgs.size()), axes.data());
      glUniform3fv(program.uniform("u_sg_power"), GLsizei(sgs.size()), powers.data());
    }
  }
  int samples_;
  std::vector<std::unique_ptr<ClothBsdf>> bsdfs_;
};
}  // namespace

RuntimeMethod sgpoint_method() {
  RuntimeMethod m;
  m.name = "sgpoint";
  m.kiosk_rung = true;  // the kiosk's method for a bundle without weighting tables
  m.glsl = kGlsl;
  m.make_gpu = [](const gpu::ClothMethodSetup& s) { return std::make_unique<SgpointCloth>(s.tangent_samples); };
  m.cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs,
              const TableSource& /*tables*/) {
    return CpuShade{sgpoint_radiance(b, facing(f, wo), wo, sgs), 0.0};
  };
  return m;
}

}  // namespace weft::methods
