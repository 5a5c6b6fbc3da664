#pragma once
// Methods iwasaki and iwasaki_vertex's GPU side: cloth drawn with the weighting tables (iwasaki.glsl,
// called from iwasaki.frag or iwasaki_vertex_pass.frag) from a bundle's baked
// data: per fabric the weighting-table textures, per occluded object the per-SG visibility
// (and, per pixel, a de-indexed mesh), κ once. Knob edits (A, γ) are uniforms; a fabric preset without baked tables
// cannot be shown (GpuError naming it). Evaluated per pixel (method `iwasaki`) or per vertex and
// interpolated (`iwasaki_vertex`: same function, iwasaki.glsl, in a fragment pass with one texel
// per vertex and SG, vertex_pass.h; the draw cuts each SG's interpolated radiance by the facet's
// plane, as the per-pixel rungs do). With broad-lobe quadrature (`iwasaki_quadrature`,
// `iwasaki_vertex_quadrature`) the broad SGs are shaded in that pass instead, by
// broad_lobe_quadrature.glsl, and added per vertex or blended into the per-pixel iwasaki.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/shading_data.h"
#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "gl/gl_program.h"
#include "gl/gpu_mesh.h"
#include "methods/cloth_method.h"
#include "methods/iwasaki/iwasaki_textures.h"
#include "methods/iwasaki/iwasaki_visibility.h"
#include "scene/scene.h"

namespace weft::gpu {

// The programs a method drawn on the weighting tables runs (embedded shader names, in link order),
// and the uniforms it adds: iwasaki's own (iwasaki_shaders()), or a layer over it (sheer).
struct IwasakiShaders {
  std::vector<std::string_view> pixel_vs, pixel_fs;    // per pixel: the cloth's draw
  std::vector<std::string_view> pass_fs;               // per vertex: the pass (on fullscreen_triangle_vs())
  std::vector<std::string_view> vertex_vs, vertex_fs;  // per vertex: the draw interpolating the pass's results
  // Uniforms of one object's draw beyond iwasaki's, on the program in use (per pixel: the draw;
  // per vertex: the pass), given its fabric and the SGs drawn (zero-amplitude lobes left out).
  std::function<void(const GlProgram&, const Fabric&, const SgLighting&)> upload;
  // SgVisibility::compute's `above_horizon`: d looked up where iwasaki.glsl shades a lobe whose
  // axis is below a vertex's surface; false for a layer that reads d at the SG axes (sheer).
  bool sdf_above_horizon = true;
  // Per (vertex, SG) the exact visible share V_k from the bundle's visibility masks
  // (SgVisibility::from_mask) instead of the SDF's d and ∇d (iwasaki.glsl's u_visibility_open_share).
  bool open_share_masks = false;
  // The broad SGs (λ < kBroadLobeSharpness) by quadrature per vertex (broad_lobe_quadrature.h),
  // with cell bits from the bundle's visibility masks; iwasaki shades the others. pass_fs then
  // computes the broad part (plus, per vertex, iwasaki's); per pixel, pixel_fs adds the pass's
  // results blended over the triangle's vertices.
  bool broad_lobe_quadrature = false;
  // Per vertex: the pass writes each SG's radiance in its own block of rows, and the draw
  // (vertex_vs, vertex_fs, built with SG_GROUPS = ⌈SGs/4⌉) cuts each by the facet's plane
  // (iwasaki_vertex.vert and .frag); false: one value per vertex, the draw interpolates it.
  bool facet_per_sg = false;
  // The programs read a textured cloth's thread maps (thread_maps.glsl) where the albedos apply.
  bool thread_maps = false;
  // A normal map is drawn: per pixel the program turns the shading frame (cloth_normal_map.glsl);
  // per vertex (with facet_per_sg) the passes shade the surface's frame, having no texel, and the
  // draw multiplies each SG's parts by the map's ratio (vertex_normal_map.glsl).
  bool normal_maps = false;
};
// iwasaki's GLSL in link order (the model, SG lighting, T's grid, the facet's horizon, iwasaki.glsl):
// what every program on its data links before its own parts, and what the parity tests compile.
const std::vector<std::string_view>& iwasaki_glsl();
// Whether the per-vertex pass's values depend on the threads' albedos: not for iwasaki's own
// passes (they keep the light per unit albedo), for a layer's that may (sheer).
bool pass_holds_albedo(const IwasakiShaders& shaders);
IwasakiShaders iwasaki_shaders();
IwasakiShaders iwasaki_quadrature_shaders();

class VisibleVertices;

class IwasakiCloth : public ClothMethod {
public:
  enum class Evaluation { per_pixel, per_vertex };
  explicit IwasakiCloth(std::shared_ptr<const ShadingData> data, Evaluation evaluation = Evaluation::per_pixel,
                        IwasakiShaders shaders = iwasaki_shaders());
  ~IwasakiCloth() override;
  size_t add_object(size_t scene_index, const TriangleMesh& mesh, const Fabric& fabric) override;
  // A colour-only edit (the albedos alone changed) keeps the per-vertex pass's values: they hold
  // the light per unit albedo (iwasaki_vertex_pass.frag), the draw applies the albedo.
  void set_fabric(size_t handle, const Fabric& fabric) override;
  bool set_thread_maps(size_t handle, const ThreadMaps& maps) override;
  bool draws_normal_maps() const override;
  // draw() computes the object's per-(vertex, SG) visibility itself when the lighting's axes or
  // sharpnesses changed since it was last set; a kiosk computes it off the render thread instead:
  // prepare_lighting is safe on any thread (it reads only what add_object fixed), set_lighting
  // uploads its result (GL thread). Both take the lighting as given to draw().
  void draw(size_t handle, const glm::mat4& view_projection, const glm::vec3& eye, const SgLighting& sgs) override;
  std::optional<SgVisibility> prepare_lighting(size_t handle, const SgLighting& sgs) const override;  // empty: unoccluded
  void set_lighting(size_t handle, const SgLighting& sgs, const SgVisibility& values) override;
  bool has_visibility(size_t handle) const;
  void set_vertex_refresh(int shares) override { vertex_shares_ = shares < 1 ? 1 : shares; }
  void set_broad_lobe_refresh(int shares) override { broad_shares_ = shares < 1 ? 1 : shares; }
  void refresh_all() override;
  void set_clock(double seconds) override { clock_ = seconds; }
  bool reuse_follows_camera() const override { return evaluation_ == Evaluation::per_vertex && shaders_.facet_per_sg; }
  bool weave_terms_per_pixel() const override { return evaluation_ == Evaluation::per_pixel; }
  // Per vertex: the passes compute only the vertices the frame shows (visible_vertices.h), where
  // the GL can mark them; on by default.
  void set_visible_vertices_only(bool on) override { visible_only_ = on; }
  bool draw_depth(size_t handle, const glm::mat4& view_projection) override;
  // How many of the object's vertices the last draw marked visible; its vertex count where it
  // computed them all (for tests).
  size_t visible_vertices(size_t handle) const;
  std::vector<float> vertex_values(size_t handle, int* block_texels) const override;
  std::optional<ShownVertices> shown_vertices(size_t handle) const override;

private:
  struct Object;
  const WeightingTablesTexture& tables_for(const Fabric& fabric);
  SgVisibility values_for(const Object& o, const SgLighting& drawn) const;  // per (vertex, SG), for the lighting drawn
  std::shared_ptr<const ShadingData> data_;
  Evaluation evaluation_;
  IwasakiShaders shaders_;
  GlProgram program_;                       // per pixel: the cloth's draw; per vertex: the vertex pass
  std::unique_ptr<GlProgram> broad_pass_;    // per pixel with broad-lobe quadrature: the vertex pass
  // Per vertex with broad-lobe quadrature: iwasaki's own pass for the SGs that are not broad, so
  // their blocks do not run inside the quadrature's larger program (VertexPass::run_shares).
  std::unique_ptr<GlProgram> narrow_pass_;
  std::unique_ptr<GlProgram> draw_program_;  // per vertex: the draw interpolating the pass's results
  // IwasakiShaders::facet_per_sg: the draw per (SG_GROUPS, NORMAL_MAPPED). Without a normal map the
  // map's ratio is compiled out: llvmpipe pays for that code in every pixel even when no pixel
  // takes it (the cloth stage ~4× on the showroom).
  std::map<std::pair<int, bool>, std::unique_ptr<GlProgram>> facet_draws_;
  const GlProgram& facet_draw(int sgs, bool normal_mapped);
  std::unique_ptr<KappaTexture> kappa_;
  WhiteTexture white_;  // thread_maps.glsl's samplers on untextured cloth
  std::map<std::string, std::unique_ptr<WeightingTablesTexture>> tables_;
  std::vector<std::unique_ptr<Object>> objects_;
  int vertex_shares_ = 1;
  double clock_ = 0.0;
  int broad_shares_ = 1;
  std::unique_ptr<VisibleVertices> visible_;  // per vertex, opaque, where supported
  bool visible_only_ = true;
};

}  // namespace weft::gpu
