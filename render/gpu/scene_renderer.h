#pragma once
// Draws a showroom scene with one runtime method into a linear float target: cloth with the
// method's shader, Lambertian surfaces (floor, occluders) with their SG irradiance, shadowed by
// the bundle's baked visibility when it has theirs (computed per vertex on the CPU whenever the
// lighting changes, not per pixel per frame).
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "methods/mdfrot.h"
#include "methods/sheen.h"
#include "methods/thin.h"
#include "gpu/gl_program.h"
#include "gpu/gpu_mesh.h"
#include "gpu/iwasaki_cloth.h"
#include "runtime/azimuthal_table.h"
#include "runtime/weighting_tables.h"
#include "image/image.h"
#include "scene/scene.h"

namespace weft::gpu {

// The GPU methods (DESIGN.md §4). A new one is a value here and a row in scene_renderer.cpp's
// method table (name, fragment shader parts, whether the cloth is see-through).
enum class Method {
  sgpoint,
  sheen,
  mdfrot,
  thin,
  iwasaki,   // seed 000 per pixel: needs the bundle's tables (IwasakiBundleData)
  iwasaki_vertex,  // seed 000 per vertex, radiance interpolated: same tables, a fraction of the cost
  mizutani,  // seed 001: the bundle's weighting tables, or the caller's (MizutaniTableSource) at construction
};
Method parse_method(const std::string& name);  // throws std::invalid_argument listing the methods
std::string method_name(Method method);
std::vector<std::string> method_names();
// Seed 000's tables (a bundle's IwasakiBundleData): iwasaki and iwasaki_vertex cannot draw
// without them; mizutani also reads their W tables when given (else the caller bakes them).
bool uses_seed000_tables(Method method);
bool reads_seed000_tables(Method method);
// The same by name; false for names that are no GPU method.
bool uses_seed000_tables(const std::string& method_name);
bool reads_seed000_tables(const std::string& method_name);

// Method::mizutani's tables where the bundle has none: the azimuthal table always, and the W
// tables of a fabric the bundle did not bake for the paper's tangent samples. Computing them is
// baking (render/bake: a minute on two cores), which stays out of the kiosk's executable, so the
// renderer takes it from its caller: the offline commands pass the baker (app/gpu_render.cpp);
// without one, Method::mizutani throws GpuError.
struct MizutaniTableSource {
  std::function<AzimuthalTable()> azimuthal;
  std::function<WeightingTables(const Fabric& fabric, std::array<int, 2> tangent_samples)> weighting;
};

class SceneRenderer {
public:
  // Needs a current GLES 3 context. `fabrics[i]` is the fabric of the i-th cloth object.
  // Method::iwasaki(_vertex) draws cloth from `iwasaki` (a bundle's seed 000 tables; required);
  // Method::mizutani takes its W tables from there when they were baked for the paper's samples
  // (else from `mizutani_tables`).
  SceneRenderer(const Scene& scene, std::vector<Fabric> fabrics, Method method, int tangent_samples = 16,
                std::shared_ptr<const IwasakiBundleData> iwasaki = nullptr,
                const MizutaniTableSource& mizutani_tables = {});
  ~SceneRenderer();

  // A lighting change's CPU work: each Lambertian object's per-vertex irradiance (with the
  // bundle's visibility where it has one: methods/lambert_visibility.h) and each occluded cloth's
  // per-(vertex, SG) visibility. prepare_lighting reads only what the constructor fixed, so it may
  // run on another thread while this renderer draws (the kiosk does: a moving probe or the
  // rotation knob must not stall frames); set_lighting(PreparedLighting) uploads it (GL thread).
  struct PreparedLighting {
    SgLighting sgs;
    std::vector<std::vector<glm::vec3>> irradiance;     // per object; empty for cloth
    std::vector<std::optional<SgVisibility>> cloth;      // per object; set for occluded seed 000 cloth
  };
  PreparedLighting prepare_lighting(const SgLighting& sgs) const;  // throws GpuError for > 40 SGs
  void set_lighting(const PreparedLighting& lighting);
  void set_lighting(const SgLighting& sgs);  // both steps at once
  // Lambertian objects shaded with the bundle's visibility (tests, logs).
  size_t shadowed_lambertian_objects() const;
  // Knob edits: new thread albedo / gloss for a cloth object, no re-bake.
  void set_fabric(size_t cloth_index, const Fabric& fabric);
  // Renders into the currently bound framebuffer of size width × height.
  void draw(const Camera& camera, int width, int height);

private:
  struct Object;
  std::vector<std::unique_ptr<Object>> objects_;
  std::unique_ptr<GlProgram> cloth_program_, lambert_program_, background_program_;
  Method method_;
  std::unique_ptr<IwasakiCloth> iwasaki_;  // Method::iwasaki(_vertex) only
  std::shared_ptr<const IwasakiBundleData> bundle_;  // the bundle's visibility (any method) and κ
  SgLighting sgs_;
  int tangent_samples_;
  // Method::mizutani: the method's own tables (cloth objects hold their weighting textures).
  std::unique_ptr<AzimuthalTable> azimuthal_;
  std::unique_ptr<ClothBsdf> mizutani_cloth(const Fabric& fabric) const;
};

// The frame as linear radiance (row 0 at the top) from a float target of the given size.
Image read_linear_image(int width, int height);

// Tone-maps a float texture to the bound framebuffer: the write_png operator.
class ToneMapper {
public:
  ToneMapper();
  void draw(GLuint linear_texture, float exposure) const;

private:
  GlProgram program_;
};

}  // namespace weft::gpu
