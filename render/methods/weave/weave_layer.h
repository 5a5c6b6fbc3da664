#pragma once
// The weave layer's GPU side (methods/weave/weave_ratio.h): after a fabric-level method has drawn
// a cloth object, multiplies the colour where the object lies by the layer's factor (blending
// dst·src), so close-ups show each thread and distant cloth keeps the method's shading. One draw
// of the mesh with its UVs, the factor per pixel (Terms): under a method that shades the canonical
// model per pixel (ClothMethod::weave_terms_per_pixel) all its terms per pixel; under a per-vertex
// method the fabric level per vertex from a vertex pass, interpolated as the method's shading is,
// with each float's lighting per pixel over it (so the factor lifts the method's interpolated
// shading to the pixel's own) or from a per-vertex table (weave_float_table.h: no light per pixel,
// far coarser up close). Skipped outright where no vertex in view can show a footprint finer than
// the coarse one (weave_reach.h), and a vertex pass skips each vertex that cannot.
#include <algorithm>
#include <map>
#include <memory>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "core/weave_layout.h"
#include "gl/gl_program.h"
#include "gl/gl_texture.h"
#include "gl/gpu_mesh.h"
#include "methods/cloth_method.h"
#include "methods/fabric_uniforms.h"
#include "methods/vertex_pass/vertex_pass.h"
#include "methods/vertex_pass/visible_vertices.h"
#include "methods/weave/weave_lights.h"
#include "methods/weave/weave_ratio.h"
#include "methods/weave/weave_reach.h"
#include "scene/scene.h"

namespace weft::gpu {

// The layout's and curves' uniforms of weave_layout.glsl (the program is in use).
void upload_weave_layout(const GlProgram& program, const WeaveLayout& layout, const Fabric& fabric);
// The #defines the weave GLSL needs for `q_groups` groups of four SGs.
std::string weave_defines(int q_groups);
// u_weave_tilt_spreads (weave_ratio.glsl) from the bsdf's samples (the program is in use).
void upload_weave_tilt_spreads(const GlProgram& program, const ClothBsdf& bsdf);

class WeaveLayer {
public:
  // One cloth object: its mesh (kept by the caller, which must outlive the layer), fabric and
  // each vertex's weave coordinates (scene/weave_scale.h's weave_coordinates). Returns its handle.
  // Needs a current GLES 3 context.
  size_t add_object(const TriangleMesh& mesh, const Fabric& fabric, std::vector<glm::dvec2> st);
  // A knob edit: the factor follows the new colours and gloss, and a new preset's weave at its
  // own size (`st`: the vertices' weave coordinates for that fabric, as add_object's).
  void set_fabric(size_t handle, const Fabric& fabric, std::vector<glm::dvec2> st);
  // Whether object `handle` can show its weave in `view` (weave_reach.h): some vertex in view
  // with a footprint under kWeaveCoarseFootprint. Keeps each vertex's footprint for the next
  // draw, whose vertex passes skip the vertices at or above it.
  bool resolves(size_t handle, const WeaveView& view);
  // Where the object's weave can show (weave_reach.h).
  const WeaveReach& reach(size_t handle) const { return *objects_.at(handle)->reach; }
  // Where the factor's terms come from (the scene renderer sets it from its method,
  // ClothMethod::weave_terms_per_pixel, and the kiosk's choice for per-vertex rungs).
  enum class Terms {
    pixel,         // all per pixel: over a method that shades per pixel (the default)
    vertex_table,  // the fabric level and each float's lighting per vertex (weave_float_table.h): no light per pixel
    // Each float's lighting per pixel, over the fabric level per vertex: the factor lifts the
    // per-vertex method's interpolated shading to the pixel's resolved shading.
    pixel_over_vertex,
  };
  void set_terms(Terms terms) { terms_ = terms; }
  Terms terms() const { return terms_; }
  // On (the default, where the GL has GLES 3.2): the vertex pass computes only the vertices of
  // triangles the frame shows (vertex_pass/visible_vertices.h); the frame is the same.
  void set_visible_vertices_only(bool on) { visible_only_ = on; }
  // Temporal reuse of the per-vertex terms and tables (VertexPass::run_share): each draw
  // recomputes 1/shares of the vertices in reach and keeps the others' (default 1: all). A vertex
  // that comes into reach, and every vertex after a lighting, knob or refresh_all(), is computed
  // at once.
  void set_vertex_refresh(int shares) { shares_ = std::max(shares, 1); }
  void refresh_all();
  // The most lights set_lighting takes under this GL's varyings (kMaxSgs at most; the per-vertex
  // terms carry two vec4 a group of four). Needs a current GLES 3 context.
  int max_lights() const;
  // The lights the factor takes and each vertex's visibility of them (weave_lighting, with at
  // most kMaxSgs lights; its visibility of this object's mesh or empty). Throws GpuError for
  // lighting of another mesh or more lights than the shaders hold (max_lights).
  void set_lighting(size_t handle, const WeaveLighting& lighting);
  // Multiplies the bound framebuffer by the factor where the object is drawn (depth LEQUAL, no
  // depth or alpha writes); restores blending and depth state after: the view of the last
  // resolves(handle, …). `shown`: the vertices the method's draw of the object just showed in
  // this view (ClothMethod::shown_vertices), where it marked them; else the layer marks them itself.
  // Throws GpuError before the object's first set_lighting.
  void draw(size_t handle, const glm::mat4& view_projection, const glm::vec3& eye,
            std::optional<ClothMethod::ShownVertices> shown = std::nullopt);

private:
  struct Object {
    const TriangleMesh* source = nullptr;
    std::unique_ptr<GpuMesh> mesh;
    // The per-vertex terms and the mesh's marks in visible_: made on the first draw that takes its
    // terms per vertex, so that a layer over `iwasaki` holds no vertex-pass target.
    std::unique_ptr<VertexPass> pass;
    std::unique_ptr<VertexPass> table;  // the per-float table from pass's terms (weave_float_table.h)
    size_t marks = 0;
    std::unique_ptr<ClothBsdf> bsdf;
    std::unique_ptr<WeaveLayout> layout;
    std::unique_ptr<WeaveReach> reach;  // for layout's rows
    std::vector<float> footprints;      // each vertex's, in resolves' view
    // Footprints at the vertex passes' texels (weave_reach.glsl): this draw's and the one's before.
    GlTexture reach_texels[2];
    int reach_now = 0;
    bool reach_filled = false;
    std::vector<glm::dvec2> st;  // each vertex's weave coordinates
    bool lit = false;              // set_lighting called
    SgLighting lights;
    GlTexture visibility;          // weave_visibility.glsl's texels; unused while `occluded` is false
    bool occluded = false;
    int visibility_width = 1, visibility_rows = 1;
  };
  struct Programs {
    std::unique_ptr<GlProgram> pass, table, draw;  // pass: with terms per vertex; table: vertex_table only
  };
  const Programs& programs(int q_groups, Terms terms);
  VertexPass& vertex_pass(Object& o);
  void upload_reach(Object& o);  // o.footprints at o.pass's texels
  std::vector<std::unique_ptr<Object>> objects_;
  std::map<std::pair<int, Terms>, Programs> programs_;  // by Q_GROUPS and terms
  std::unique_ptr<VisibleVertices> visible_;            // where supported
  bool visible_only_ = true;
  Terms terms_ = Terms::pixel;
  int shares_ = 1;
  // Each sample's lobes widened by its arc's tilts: a few stand for the float, satin's included.
  int tangent_samples_ = kWeavePixelSamples;
};

}  // namespace weft::gpu
