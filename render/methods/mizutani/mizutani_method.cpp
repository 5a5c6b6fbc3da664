#include "methods/mizutani/mizutani_method.h"

#include <memory>
#include <string>

#include "runtime/azimuthal_table.h"
#include "gl/gl_error.h"
#include "runtime/paper_tangent_samples.h"
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
  MizutaniCloth(std::shared_ptr<const ShadingData> bundle, TableSource tables)
      : ProgramCloth(gpu::with_main(kGlsl, "mizutani.frag"),  // its light arrays are sized at compile time
                     "#define MAX_SGS " + std::to_string(gpu::kMizutaniMaxSgs) + "\n"),
        bundle_(std::move(bundle)),
        tables_(std::move(tables)),
        azimuthal_(checked(tables_).azimuthal()) {}
  size_t add_object(size_t, const TriangleMesh& mesh, const Fabric& fabric) override {
    // mizutani's W is iwasaki's: a bundle's tables serve when baked for the same samples.
    const auto samples = paper_tangent_samples(fabric);
    const WeightingTables* from_bundle = nullptr;
    if (bundle_)
      if (auto t = bundle_->tables.find(fabric.name); t != bundle_->tables.end() && t->second.tangent_samples == samples)
        from_bundle = &t->second;
    Object o;
    if (from_bundle) {
      o.textures = std::make_unique<gpu::MizutaniTextures>(*from_bundle, azimuthal_);
    } else {
      o.textures = std::make_unique<gpu::MizutaniTextures>(tables_.weighting(fabric, samples, 0), azimuthal_);
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
  // The azimuthal table is in no bundle, so mizutani draws only where tables can be baked.
  static const TableSource& checked(const TableSource& t) {
    if (!t) throw gpu::GpuError("method mizutani bakes its tables as it starts: only the offline commands (weft render, weft bench) can show it");
    return t;
  }
  std::shared_ptr<const ShadingData> bundle_;
  TableSource tables_;
  AzimuthalTable azimuthal_;
  std::vector<Object> objects_;
};
}  // namespace

RuntimeMethod mizutani_method() {
  RuntimeMethod m;
  m.name = "mizutani";
  m.weighting_tables = WeightingTablesUse::read_when_given;
  m.glsl = kGlsl;
  m.make_gpu = [](const gpu::ClothMethodSetup& s) { return std::make_unique<MizutaniCloth>(s.bundle, s.tables); };
  m.cpu = [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs,
              const TableSource& tables) {
    const TableBsdf t = stress_table_bsdf(b.fabric(), tables);
    return CpuShade{mizutani_radiance(t.bsdf, *t.tables, stress_azimuthal_table(tables), facing(f, wo), wo, sgs).radiance, 0.0};
  };
  return m;
}

}  // namespace weft::methods
