#pragma once
// A runtime method's GPU side, as the scene renderer drives it: the cloth objects it draws, knob
// edits, the lighting's per-object CPU work, and one object's draw. Each method implements it in
// its folder (render/methods/<name>/) and the registry (methods/registry.h) makes it.
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/shading_data.h"
#include "runtime/table_source.h"
#include "core/fabric.h"
#include "core/spherical_gaussian.h"
#include "methods/sg_visibility.h"
#include "methods/thread_map_textures.h"
#include "scene/mesh.h"

namespace weft::gpu {

// What a method's GPU side is made with.
struct ClothMethodSetup {
  int tangent_samples = 16;  // per thread, where the method samples the curves at will
  // A bundle's weighting tables (null without); methods that need them throw GpuError without.
  std::shared_ptr<const ShadingData> bundle;
  // Tables no bundle holds (mizutani's): the offline commands' baker; empty in the kiosk.
  TableSource tables;
};

class ClothMethod {
public:
  virtual ~ClothMethod() = default;
  // Scene object `scene_index` (cloth), with its mesh (kept by the caller for the method's
  // lifetime) and fabric; returns the handle the calls below take. Needs a current GLES 3 context.
  virtual size_t add_object(size_t scene_index, const TriangleMesh& mesh, const Fabric& fabric) = 0;
  // A textured cloth's thread maps (methods/thread_map_textures.h: each thread's albedo times the
  // texel), after add_object. Returns false when the method draws the object without them.
  virtual bool set_thread_maps(size_t handle, const ThreadMaps& maps) {
    (void)handle, (void)maps;
    return false;
  }
  // Whether the method applies a normal map given with set_thread_maps (per pixel); false: it
  // draws the object with its surface's normals.
  virtual bool draws_normal_maps() const { return false; }
  // A knob edit: new thread albedo / gloss, no re-bake. Throws GpuError (and changes nothing)
  // for a fabric the method cannot show.
  virtual void set_fabric(size_t handle, const Fabric& fabric) = 0;
  // A lighting change's CPU work for one object: per-(vertex, SG) visibility for occluded cloth;
  // empty when the method has none. Safe on any thread: reads only what add_object fixed.
  virtual std::optional<SgVisibility> prepare_lighting(size_t handle, const SgLighting& sgs) const {
    (void)handle, (void)sgs;
    return std::nullopt;
  }
  // Uploads prepare_lighting's result for the lighting `sgs` (GL thread).
  virtual void set_lighting(size_t handle, const SgLighting& sgs, const SgVisibility& prepared) {
    (void)handle, (void)sgs, (void)prepared;
  }
  // Temporal reuse of per-vertex work: each draw recomputes 1/shares of each object's vertices
  // (the next share each time) and keeps the others' values from earlier draws, so a camera
  // moving slowly (the turntable) costs a share of the pass per frame. A change of fabric or
  // lighting recomputes every vertex on the next draw; refresh_all() asks the same after the eye
  // jumped. shares = 1 (the default): every vertex every draw. A method without per-vertex
  // work ignores both.
  virtual void set_vertex_refresh(int shares) { (void)shares; }
  // The same for the broad lobes' quadrature alone (methods/broad_lobe_bits.h), whose radiance
  // changes slowly with the view: recomputed once every max(shares, vertex refresh) draws.
  virtual void set_broad_lobe_refresh(int shares) { (void)shares; }
  virtual void refresh_all() {}
  // The time of the next draw, in seconds on the caller's clock (any origin, non-decreasing). With
  // temporal reuse, a method that can carries each kept per-vertex value on to it along the line
  // through that value's last two computations (methods/vertex_pass/vertex_history.glsl): a turning
  // camera's kept values lag the view far less. A caller that never sets it gets plain reuse.
  virtual void set_clock(double seconds) { (void)seconds; }
  // Whether kept per-vertex values follow the clock (and vertices seen edge-on are recomputed at
  // every draw): temporal reuse then costs a fraction of what holding values does, and a caller
  // may reuse by default.
  virtual bool reuse_follows_camera() const { return false; }
  // Whether the weave layer over this method takes its fabric-level terms per pixel: worth 16
  // tangent samples × SGs a pixel only under a method that shades the canonical model per pixel
  // (iwasaki). Otherwise (false) they are per vertex, interpolated as a per-vertex method's
  // shading is, so that the layer's ratio divides that interpolation out, and cheap under a cheap
  // per-pixel approximation whose own error is larger than what per-pixel terms would fix.
  virtual bool weave_terms_per_pixel() const { return false; }
  // Per-vertex work only for the vertices the frame shows, where the method can tell (the same
  // frame, less work); on by default. Off: every vertex (tests compare the two).
  virtual void set_visible_vertices_only(bool on) { (void)on; }
  // The vertices of `handle` its last draw showed, where it marked them (vertex_pass/visible_vertices.h):
  // the marks' buffer (a uint per vertex) and the stamp a shown vertex holds, so that a layer drawn
  // over the object from the same view takes them instead of rasterising the mesh again.
  struct ShownVertices {
    unsigned buffer = 0;  // a GL buffer name
    unsigned stamp = 0;
  };
  virtual std::optional<ShownVertices> shown_vertices(size_t handle) const {
    (void)handle;
    return std::nullopt;
  }
  // The object's per-vertex values as its last draw computed them (RGBA float texels, a block of
  // rows per value, vertex_pass.h's layout) and the texels a block holds; empty where the method
  // has none. For tests and diagnostics (a driver's NaN found at its vertex and SG).
  virtual std::vector<float> vertex_values(size_t handle, int* block_texels) const {
    (void)handle, (void)block_texels;
    return {};
  }
  // Writes the object's depth alone into the bound framebuffer as draw() places it, a few depth
  // steps farther: draw() afterwards (GL_LESS) then shades little behind the front, and what it
  // shows is the same, since every fragment it drops lies behind one that wins anyway (ties
  // still go to the first drawn). False (nothing drawn) where the method cannot.
  virtual bool draw_depth(size_t handle, const glm::mat4& view_projection) {
    (void)handle, (void)view_projection;
    return false;
  }
  // Draws the object into the bound framebuffer; blending and depth writes are the caller's.
  virtual void draw(size_t handle, const glm::mat4& view_projection, const glm::vec3& eye, const SgLighting& sgs) = 0;
};

}  // namespace weft::gpu
