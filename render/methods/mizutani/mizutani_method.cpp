#include "methods/mizutani/mizutani_method.h"

#include <memory>
#include <string>

#include "bake/azimuthal_table.h"
#include "bake/bake_selection.h"
#include "bake/weighting_bake.h"
#include "methods/cpu_evaluation.h"
#include "methods/fabric_uniforms.h"
#include "methods/mizutani/mizutani.h"
#include "methods/mizutani/mizutani_textures.h"
#include "methods/program_cloth.h"

namespace weft::methods {

namespace {
const std::vector<std::string_view> kGlsl = {"microcylinder.glsl", "hemisphere_grid.glsl", "mizutani.glsl"};

class MizutaniCloth : public gpu::ProgramCloth {
public:
  explicit MizutaniCloth(std::shared_ptr<const IwasakiBundleData> bundle)
      : ProgramCloth(gpu::with_main(kGlsl, "mizutani.frag"),  // its light arrays are sized at compile time
                     "#define MAX_SGS " + std::to_string(gpu::kMizutaniMaxSgs) + "\n"),
        bundle_(std::move(bundle)),
        azimuthal_(bake_azimuthal_table()) {}
  size_t add_object(size_t, const TriangleMesh& mesh, const Fabric& fabric) override {
    // Seed 001's W is seed 000's: a bundle's tables serve when baked for the same samples.
    const auto samples = paper_tangent_samples(fabric);
    const WeightingTables* from_bundle = nullptr;
    if (bundle_)
      if (auto t = bundle_->tables.find(fabric.name); t != bundle_->tables.end() && t->second.tangent_samples == samples)
        from_bundle = &t->second;
    Object o;
    if (from_bundle) {
      o.textures = std::make_unique<gpu::MizutaniTextures>(*from_bundle, azimuthal_);
    } else {
      BakeSettings settings;
      settings.tangent_samples = samples;
      o.textures = std::make_unique<gpu::MizutaniTextures>(bake_weighting_tables(fabric, settings), azimuthal_);
    }
    objects_.push_back(std::move(o));
    set_fabric(objects_.size() - 1, fabric);
    return add_mesh(mesh);
  }
  // Knob edits keep the tables (they depend on the curves, not on A or γ).
  void set_fabric(size_t handle, const Fabric& fabric) override {
    objects_.at(handle).bsdf = std::make_unique<ClothBsdf>(fabric, paper_tangent_samples(fabric));
  }

private:
  struct Object {
    std::unique_ptr<ClothBsdf> bsdf;
    std::unique_ptr<gpu::MizutaniTextures> textures;
  };
  void upload(size_t handle, const gpu::GlProgram& program, const SgLighting& sgs) const override {
    const Object& o = objects_.at(handle);
    gpu::upload_fabric(program, *o.bsdf);
    o.textures->bind(program);
    gpu::upload_mizutani_lights(program, sgs);
  }
  std::shared_ptr<const IwasakiBundleData> bundle_;
  AzimuthalTable azimuthal_;
  std::vector<Object> objects_;
};
}  // namespace

RuntimeMethod mizutani_method() {
  RuntimeMethod m;
  m.name = "mizutani";
  m.seed000 = Seed000Tables::read_when_given;
  m.ladder_position = 2;
  m.stability_position = 1;
  m.glsl = kGlsl;
  m.make_gpu = [](const gpu::ClothMethodSetup& s) { return std::make_unique<MizutaniCloth>(s.bundle); };
  m.cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
    const TableBsdf t = stress_table_bsdf(b.fabric());
    return CpuShade{mizutani_radiance(t.bsdf, *t.tables, stress_azimuthal_table(), facing(f, wo), wo, sgs).radiance, 0.0};
  };
  return m;
}

}  // namespace weft::methods
