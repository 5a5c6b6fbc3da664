#pragma once
// Draws a showroom scene with one runtime method into a linear float target: cloth with the
// method's shader, Lambertian surfaces (floor, occluders) with their SG irradiance, shadowed by
// the bundle's baked visibility when it has theirs (computed per vertex on the CPU whenever the
// lighting changes, not per pixel per frame).
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/spherical_gaussian.h"
#include "gl/gl_program.h"
#include "gl/gpu_mesh.h"
#include "image/image.h"
#include "methods/bundle_visibility.h"
#include "methods/cloth_method.h"
#include "methods/runtime_method.h"
#include "methods/weave/weave_lights.h"
#include "scene/scene.h"

namespace weft::gpu {

class BackdropCube;
class WeaveLayer;

// What is drawn behind the scene. `measure`: nothing (black) except behind see-through cloth,
// where the SG environment is seen as the reference sees it (the bench's accuracy frames).
// `showroom`: for every method, the SG environment softened (each lobe convolved with a
// normalised SG of sharpness kBackdropBlurSharpness: the room out of focus behind the product,
// as a photographer's shallow depth of field shows it); see-through cloth blends over it.
enum class Backdrop { measure, showroom };
inline constexpr double kBackdropBlurSharpness = 6.0;
// The softened environment: λ' = λλ_b/(λ+λ_b), amplitude rescaled so each lobe keeps its
// integral over the sphere.
SgLighting softened_environment(const SgLighting& sgs, double blur_sharpness = kBackdropBlurSharpness);

// The colour target's alpha after draw(): 1 where cloth was drawn (coverage: the backdrop and
// Lambertian surfaces leave it at 0; see-through cloth leaves its transmittance there plus what
// was behind, so any alpha > 0 is cloth). Metering and cloth masks read this, never the colour.
bool is_cloth_alpha(float alpha);

// The parts of a bundle's shading data a frame drawn with `method` reads: the method's own
// (RuntimeMethod::bake_reads), and under every method the floors' and occluders' visibility and the
// weave layer's lights' (visibility and masks). The weighting tables only where the method reads them.
ShadingParts frame_bake_reads(const methods::RuntimeMethod& method);

class SceneRenderer {
public:
  // Needs a current GLES 3 context. `fabrics[i]` is the fabric of the i-th cloth object. The
  // method's GPU side gets `iwasaki` (a bundle's weighting tables): iwasaki(_vertex) need them,
  // mizutani takes its W tables from there when they were baked for the paper's samples (else
  // from `tables`, which the offline commands fill with a baker and the kiosk leaves empty). The
  // bundle's visibility shades every method's floors.
  // `method`: an entry of the registry (methods/registry.h).
  SceneRenderer(const Scene& scene, std::vector<Fabric> fabrics, const methods::RuntimeMethod& method, int tangent_samples = 16,
                std::shared_ptr<const ShadingData> shading = nullptr, TableSource tables = {});
  ~SceneRenderer();

  // A lighting change's CPU work: each Lambertian object's per-vertex irradiance (with the
  // bundle's visibility where it has one: methods/lambert_visibility.h) and each occluded cloth's
  // per-(vertex, SG) visibility. prepare_lighting reads only what the constructor fixed, so it may
  // run on another thread while this renderer draws (the kiosk does: a moving probe or the
  // rotation knob must not stall frames); set_lighting(PreparedLighting) uploads it (GL thread).
  // With the weave on, also each cloth object's lights for the weave layer and their visibility
  // (methods/weave/weave_lights.h).
  struct PreparedLighting {
    SgLighting sgs;
    std::vector<std::vector<glm::vec3>> irradiance;     // per object; empty for cloth
    std::vector<std::optional<SgVisibility>> cloth;      // per object; set for occluded cloth on the tables
    std::vector<std::optional<WeaveLighting>> weave;     // per object; set for cloth while the weave is on
  };
  PreparedLighting prepare_lighting(const SgLighting& sgs) const;  // throws GpuError for > 40 SGs
  void set_lighting(const PreparedLighting& lighting);
  void set_lighting(const SgLighting& sgs);  // both steps at once
  // Lambertian objects shaded with the bundle's visibility (tests, logs).
  size_t shadowed_lambertian_objects() const;
  // Knob edits: new thread albedo / gloss for a cloth object, no re-bake.
  void set_fabric(size_t cloth_index, const Fabric& fabric);
  void set_backdrop(Backdrop backdrop);  // default: measure
  // What the operator should know about how the scene is drawn: a textured cloth object the method
  // draws without its texture (one line each).
  const std::vector<std::string>& warnings() const { return warnings_; }
  // Temporal reuse of the cloth's per-vertex work (ClothMethod::set_vertex_refresh, and the weave
  // layer's: WeaveLayer::set_vertex_refresh): each draw
  // recomputes 1/shares of the vertices; refresh_all(): every vertex on the next draw (the eye
  // jumped). Default 1: all, every draw.
  void set_vertex_refresh(int shares);
  void set_broad_lobe_refresh(int shares) { cloth_->set_broad_lobe_refresh(shares); }
  void refresh_all();
  // The next draw's time (ClothMethod::set_clock): kept per-vertex values follow the camera.
  void set_clock(double seconds) { cloth_->set_clock(seconds); }
  bool reuse_follows_camera() const { return cloth_->reuse_follows_camera(); }
  // The i-th cloth object's per-vertex values (ClothMethod::vertex_values), for tests and diagnostics.
  std::vector<float> cloth_vertex_values(size_t cloth_index, int* block_texels) const;
  // ClothMethod::set_visible_vertices_only and the weave layer's (on by default).
  void set_visible_vertices_only(bool on);
  // Opaque cloth's depth drawn before its shading (ClothMethod::draw_depth); on by default.
  void set_depth_prepass(bool on) { depth_prepass_ = on; }
  // The resolved weave over opaque cloth (methods/weave/weave_layer.h): where a pixel covers less
  // than about a repeat, each point shows the thread that lies there. Off by default; a
  // see-through method draws no weave; nor does cloth without UVs (no place for its threads).
  void set_weave(bool on);
  bool weave() const { return weave_on_; }
  // Over a method that shades per vertex, where each float's lighting comes from
  // (WeaveLayer::Terms): per pixel over the method's per-vertex level (true, the default: within
  // 8 % of the resolved reference up close, at a per-pixel light loop), or the per-vertex table
  // (false: no light per pixel, far less accurate up close). Over `iwasaki` the layer's terms are
  // all per pixel, over another per-pixel method from the table, either way.
  void set_weave_pixel_terms(bool on);
  bool weave_pixel_terms() const { return weave_pixel_terms_; }
  // Whether the last draw() drew the weave layer over any object (some thread was resolved).
  bool weave_drawn() const { return weave_drawn_; }
  // The cameras a viewer can be shown (the kiosk's zoom path), each turned about the vertical
  // through its pivot by any angle (the turntable), on a width × height image: a cloth object no
  // such camera can show a thread of gets no weave work at all (no lights, no visibility at a
  // lighting change, no draw). Every object is in range until this is called; the path must be
  // sampled finely enough that the eye moves less than a tenth of its distance to the cloth
  // between samples (kWeaveRangeMargin keeps that margin). Returns the cloth objects in range
  // (0 while the weave was never armed).
  struct OrbitingCamera {
    Camera camera;
    glm::dvec3 pivot{0.0};
  };
  static constexpr double kWeaveRangeMargin = 1.25;
  size_t set_weave_range(std::span<const OrbitingCamera> cameras, int width, int height);
  // Renders into the currently bound framebuffer of size width × height: the backdrop first,
  // then opaque surfaces, then see-through cloth blended over them.
  void draw(const Camera& camera, int width, int height);

private:
  struct Object;
  // Cloth object o's lights for the weave layer under `sgs`, from its baked visibility.
  WeaveLighting weave_lighting_of(const Object& o, const SgLighting& sgs) const;
  std::vector<std::unique_ptr<Object>> objects_;
  std::unique_ptr<GlProgram> lambert_program_, background_program_;
  const methods::RuntimeMethod* method_;
  std::unique_ptr<ClothMethod> cloth_;  // the method's GPU side: draws every cloth object
  std::shared_ptr<const ShadingData> bundle_;  // the bundle's visibility (any method) and κ
  SgLighting sgs_, backdrop_sgs_;
  std::unique_ptr<BackdropCube> backdrop_cube_;  // Backdrop::showroom: backdrop_sgs_, filled by set_lighting
  std::unique_ptr<WeaveLayer> weave_;  // made on the first set_weave(true)
  bool weave_on_ = false, weave_pixel_terms_ = true, weave_drawn_ = false;
  int weave_max_lights_ = 0;           // the layer's max_lights, read on the GL thread
  bool visible_only_ = true;  // set_visible_vertices_only
  int vertex_refresh_ = 1;    // set_vertex_refresh
  bool depth_prepass_ = true;
  std::map<const TextureImage*, std::unique_ptr<ThreadMapTexture>> textures_;  // each image once
  std::map<const TextureImage*, std::unique_ptr<NormalMapTexture>> normal_textures_;  // linear, each once
  std::vector<std::string> warnings_;
  Backdrop backdrop_ = Backdrop::measure;
  // The scene's bounding sphere: the far plane reaches past it whatever the file's units (a
  // product modelled in millimetres is metres across in numbers).
  glm::dvec3 bounds_centre_{0.0};
  double bounds_radius_ = 0.0;
};

// The frame as linear radiance (row 0 at the top) from a float target of the given size.
Image read_linear_image(int width, int height);

// Tone-maps a float texture to the bound framebuffer: the write_png operator (image/tone_map.h).
class ToneMapper {
public:
  ToneMapper();
  void draw(GLuint linear_texture, float exposure) const;

private:
  GlProgram program_;
};

}  // namespace weft::gpu
