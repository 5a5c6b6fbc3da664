#include "methods/iwasaki/iwasaki_cloth.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/type_ptr.hpp>

#include "gl/gl_error.h"
#include "methods/broad_lobe_bits.h"
#include "methods/bundle_visibility.h"
#include "methods/fabric_uniforms.h"
#include "methods/program_cloth.h"
#include "methods/iwasaki/vertex_normal_map.h"
#include "methods/vertex_pass/vertex_pass.h"
#include "methods/vertex_pass/visible_vertices.h"
#include "methods/weave/weave_ratio.h"
#include "shaders/embedded_shaders.h"

namespace weft::gpu {

namespace {
constexpr int kMaxSgs = 40;  // MAX_SGS in iwasaki.glsl

// Per pixel: the cloth's own draw. Per vertex: the fragment pass over the vertex texels
// (vertex_pass.h); the draw that interpolates its results is draw_program_.
GlProgram make_program(IwasakiCloth::Evaluation e, const IwasakiShaders& s) {
  if (e == IwasakiCloth::Evaluation::per_vertex) return GlProgram(fullscreen_triangle_vs(), program_source(s.pass_fs));
  return GlProgram(program_source(s.pixel_vs), program_source(s.pixel_fs));
}

// The SGs a draw shades with: a fit's empty lobes (zero amplitude) do no work.
SgLighting shaded(const SgLighting& sgs) {
  SgLighting out;
  for (const auto& g : sgs)
    if (std::max({g.amplitude.r, g.amplitude.g, g.amplitude.b}) > 0.0) out.push_back(g);
  return out;
}

// The mesh's UVs as (u, v, 0): the attribute thread_maps.glsl's callers read at location 6.
std::vector<glm::vec3> uv_attribute(const TriangleMesh& m) {
  std::vector<glm::vec3> out(m.uvs.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = glm::vec3(float(m.uvs[i].x), float(m.uvs[i].y), 0.0f);
  return out;
}

bool same_lighting(const SgLighting& a, const SgLighting& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].axis != b[i].axis || a[i].sharpness != b[i].sharpness) return false;  // amplitude: no effect on visibility
  return true;
}
// The same lobes at the same amplitudes: what the per-vertex pass's kept radiance depends on.
bool identical_lighting(const SgLighting& a, const SgLighting& b) {
  if (!same_lighting(a, b)) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].amplitude != b[i].amplitude) return false;
  return true;
}
}  // namespace

const std::vector<std::string_view>& iwasaki_glsl() {
  static const std::vector<std::string_view> parts = {"microcylinder.glsl", "erf.glsl",          "sg_lighting.glsl",
                                                      "hemisphere_grid.glsl", "facet_horizon.glsl", "iwasaki.glsl",
                                                      "thread_maps.glsl", "normal_map_frame.glsl",
                                                      "cloth_normal_map.glsl"};
  return parts;
}

bool pass_holds_albedo(const IwasakiShaders& s) { return !(s.facet_per_sg || s.broad_lobe_quadrature); }

IwasakiShaders iwasaki_shaders() {
  IwasakiShaders s;
  s.pixel_vs = {"iwasaki.vert"};
  s.pixel_fs = iwasaki_glsl();
  s.pixel_fs.push_back("iwasaki.frag");
  s.pass_fs = iwasaki_glsl();
  s.pass_fs.push_back("vertex_pass.glsl");
  s.pass_fs.push_back("iwasaki_vertex_pass.frag");
  s.vertex_vs = {"vertex_history.glsl", "iwasaki_vertex.vert"};
  s.vertex_fs = {"microcylinder.glsl",    "erf.glsl",       "sg_lighting.glsl",      "facet_horizon.glsl",
                 "thread_maps.glsl",      "normal_map_frame.glsl", "cloth_normal_map.glsl", "vertex_normal_map.glsl",
                 "iwasaki_vertex.frag"};
  s.facet_per_sg = true;
  s.thread_maps = true;
  s.normal_maps = true;
  return s;
}

IwasakiShaders iwasaki_quadrature_shaders() {
  IwasakiShaders s = iwasaki_shaders();
  s.pixel_fs.back() = "iwasaki_quadrature.frag";
  s.pass_fs.back() = "broad_lobe_quadrature.glsl";
  s.pass_fs.push_back("iwasaki_quadrature_pass.frag");
  s.broad_lobe_quadrature = true;
  return s;
}

struct IwasakiCloth::Object {
  explicit Object(GpuMesh m) : mesh(std::move(m)) {}
  GpuMesh mesh;
  std::unique_ptr<VertexPass> pass;  // per-vertex evaluation only
  size_t marks = 0;                  // its mesh in visible_, where there is one
  unsigned shown_stamp = 0;          // the stamp of its last draw's marks (0: not marked)
  size_t vertices = 0;
  std::unique_ptr<ClothBsdf> bsdf;
  std::unique_ptr<ClothBsdf> ratio_bsdf;  // per vertex with a normal map: normal_map_ratio_bsdf(*bsdf)
  const WeightingTablesTexture* tables = nullptr;
  // Occluded objects: the bundle's PCA and the mesh (vertex frames), and the per-(vertex, SG)
  // values for the lighting they were last computed for.
  const ObjectVisibility* visibility = nullptr;
  const VisibilityMask* mask = nullptr;  // IwasakiShaders::open_share_masks
  // IwasakiShaders::broad_lobe_quadrature: the cells' bits, from this mask (all open without one).
  const VisibilityMask* broad_mask = nullptr;
  std::unique_ptr<BroadLobeBitsTexture> broad_bits;
  const TriangleMesh* source = nullptr;
  std::unique_ptr<SgVisibilityTexture> sg_visibility;
  SgLighting computed_for;
  SgLighting passed_for;  // the lighting the per-vertex pass's kept values were computed under
  ThreadMaps maps;        // a textured cloth's (set_thread_maps)
};

namespace {
// The same fabric but for its threads' albedos: what a colour knob changes.
bool same_but_albedo(const Fabric& a, const Fabric& b) {
  if (a.name != b.name || a.optical_thickness != b.optical_thickness) return false;
  for (int j = 0; j < 2; ++j) {
    const ThreadParams &p = a.threads[j], &q = b.threads[j];
    if (p.eta != q.eta || p.kd != q.kd || p.gamma_s != q.gamma_s || p.gamma_v != q.gamma_v || p.coverage != q.coverage ||
        p.curve.offsets_deg() != q.curve.offsets_deg() || p.curve.lengths() != q.curve.lengths())
      return false;
  }
  return true;
}
}  // namespace

IwasakiCloth::IwasakiCloth(std::shared_ptr<const ShadingData> data, Evaluation evaluation, IwasakiShaders shaders)
    : data_(std::move(data)), evaluation_(evaluation), shaders_(std::move(shaders)), program_(make_program(evaluation, shaders_)) {
  if (evaluation_ == Evaluation::per_vertex) {
    if (!shaders_.facet_per_sg)  // else facet_draw(), built for the SGs drawn
      draw_program_ = std::make_unique<GlProgram>(program_source(shaders_.vertex_vs), program_source(shaders_.vertex_fs));
    // The opaque rungs' draw (iwasaki_vertex.vert) places the mesh as visible_vertices.vert does.
    else if (VisibleVertices::supported())
      visible_ = std::make_unique<VisibleVertices>();
    if (shaders_.facet_per_sg && shaders_.broad_lobe_quadrature)
      narrow_pass_ = std::make_unique<GlProgram>(fullscreen_triangle_vs(), program_source(iwasaki_shaders().pass_fs));
  } else if (shaders_.broad_lobe_quadrature) {
    broad_pass_ = std::make_unique<GlProgram>(fullscreen_triangle_vs(), program_source(shaders_.pass_fs));
  }
  // Tables are looked up per fabric as cloth is added (tables_for): a bundle with no cloth has none.
  if (!data_) throw GpuError("method iwasaki needs weighting tables (bake the bundle with `weft bake`)");
  if (data_->kappa) kappa_ = std::make_unique<KappaTexture>(*data_->kappa);
}

IwasakiCloth::~IwasakiCloth() = default;

const WeightingTablesTexture& IwasakiCloth::tables_for(const Fabric& fabric) {
  auto it = tables_.find(fabric.name);
  if (it != tables_.end()) return *it->second;
  const auto t = data_->tables.find(fabric.name);
  if (t == data_->tables.end())
    throw GpuError("method iwasaki: no weighting tables baked for fabric '" + fabric.name + "' (bake the bundle with `weft bake`)");
  return *tables_.emplace(fabric.name, std::make_unique<WeightingTablesTexture>(t->second)).first->second;
}

size_t IwasakiCloth::add_object(size_t scene_index, const TriangleMesh& mesh, const Fabric& fabric) {
  const ObjectVisibility* vis = checked_visibility(*data_, scene_index, mesh);
  const bool per_vertex = evaluation_ == Evaluation::per_vertex;
  std::unique_ptr<Object> o;
  const bool quadrature = shaders_.broad_lobe_quadrature;
  if ((vis || quadrature) && !per_vertex) {  // per pixel, drawn de-indexed: every corner carries the triangle's three vertices
    std::vector<glm::vec3> corners, bary;
    const TriangleMesh drawn = deindexed(mesh, corners, bary);
    o = std::make_unique<Object>(GpuMesh(drawn));
    o->mesh.add_attribute(4, corners);
    o->mesh.add_attribute(5, bary);
    if (!drawn.uvs.empty()) o->mesh.add_attribute(6, uv_attribute(drawn));
  } else {
    o = std::make_unique<Object>(GpuMesh(mesh));
    if (!mesh.uvs.empty()) o->mesh.add_attribute(6, uv_attribute(mesh));
  }
  // Each vertex reads its own SDF values; per pixel, the pass computes the broad lobes' part.
  if (per_vertex || quadrature) o->pass = std::make_unique<VertexPass>(mesh, pass_of(mesh));
  // Per SG per vertex, the blocks' RGB hold the values: their fourth channel can hold the time.
  if (per_vertex && shaders_.facet_per_sg) o->pass->set_history(true);
  o->vertices = mesh.positions.size();
  if (per_vertex && visible_) o->marks = visible_->add_mesh(mesh, o->mesh, o->pass->texels());
  if (quadrature) {
    o->broad_bits = std::make_unique<BroadLobeBitsTexture>();
    o->broad_bits->upload(BroadLobeBits::all_open(mesh.positions.size()));
    const auto m = data_->masks.find(scene_index);
    if (vis && m != data_->masks.end() && m->second.vertex_count() == mesh.positions.size()) o->broad_mask = &m->second;
  }
  if (vis) {
    o->visibility = vis;
    if (shaders_.open_share_masks) {
      const auto m = data_->masks.find(scene_index);
      if (m == data_->masks.end() || m->second.vertex_count() != mesh.positions.size())
        throw GpuError("a method with the masks' visibility (iwasaki_mask, iwasaki_vertex_mask, *_mask_quadrature): "
                       "the bundle has no visibility mask for object " +
                       std::to_string(scene_index) + " (bake it again without `weft bake --no-masks`)");
      o->mask = &m->second;
    }
    o->source = &mesh;
    o->sg_visibility = std::make_unique<SgVisibilityTexture>();
  }
  objects_.push_back(std::move(o));
  set_fabric(objects_.size() - 1, fabric);
  return objects_.size() - 1;
}

std::optional<SgVisibility> IwasakiCloth::prepare_lighting(size_t handle, const SgLighting& sgs) const {
  const Object& o = *objects_.at(handle);
  if (!o.visibility) return std::nullopt;
  return values_for(o, shaded(sgs));
}

SgVisibility IwasakiCloth::values_for(const Object& o, const SgLighting& drawn) const {
  SgVisibility out = o.mask ? SgVisibility::from_mask(*o.mask, *o.source, drawn)
                            : SgVisibility::compute(*o.visibility, *o.source, drawn, shaders_.sdf_above_horizon);
  if (o.broad_mask) out.broad = BroadLobeBits::compute(*o.broad_mask, *o.source, drawn);
  return out;
}

void IwasakiCloth::set_lighting(size_t handle, const SgLighting& sgs, const SgVisibility& values) {
  Object& o = *objects_.at(handle);
  if (!o.visibility) return;
  const SgLighting drawn = shaded(sgs);
  if (values.vertices != o.visibility->vertex_count() || values.sgs != int(drawn.size()))
    throw GpuError("method iwasaki: visibility computed for another object or lighting");
  if (o.broad_mask && values.broad.vertices != values.vertices)
    throw GpuError("method iwasaki: the broad lobes' cell bits were not computed for this object");
  o.sg_visibility->upload(values);
  if (o.broad_mask) o.broad_bits->upload(values.broad);
  o.computed_for = drawn;
}

const GlProgram& IwasakiCloth::facet_draw(int sgs, bool normal_mapped) {
  const int groups = std::max(1, (sgs + 3) / 4);
  auto it = facet_draws_.find({groups, normal_mapped});
  if (it != facet_draws_.end()) return *it->second;
  // Three vec4 per group, the position, the normal, the warp and the UV: what the vertex stage
  // hands the fragment stage, each vec3 and vec2 counted as a whole vec4 in case the GL does not
  // pack them.
  GLint out = 0, in = 0;
  glGetIntegerv(GL_MAX_VERTEX_OUTPUT_COMPONENTS, &out);
  glGetIntegerv(GL_MAX_FRAGMENT_INPUT_COMPONENTS, &in);
  const int needed = 12 * groups + 16, limit = std::min(out, in);
  if (needed > limit)
    throw GpuError("per-vertex iwasaki: " + std::to_string(sgs) + " SGs need " + std::to_string(needed) +
                   " varying components per vertex (each SG's radiance, cut per pixel by the facet's plane), more than "
                   "this GL's " + std::to_string(limit) + " (GL_MAX_VERTEX_OUTPUT_COMPONENTS " + std::to_string(out) +
                   ", GL_MAX_FRAGMENT_INPUT_COMPONENTS " + std::to_string(in) + "): fit fewer SGs");
  char ratio[224];
  std::snprintf(ratio, sizeof ratio,
                "#define NORMAL_MAP_RATIO_BIAS %.9e\n#define NORMAL_MAP_RATIO_CAP %.9e\n#define NORMAL_MAP_FLAT_TILT %.9e\n"
                "#define BROAD_LOBE_SHARPNESS %.9e\n",
                kNormalMapRatioBias, kNormalMapRatioCap, kNormalMapFlatTilt, kBroadLobeSharpness);
  const std::string defines =
      "#define SG_GROUPS " + std::to_string(groups) + "\n#define MAX_PASS_VALUES (4 * SG_GROUPS)\n#define NORMAL_MAPPED " + (normal_mapped ? "1" : "0") + "\n" + ratio;
  auto program = std::make_unique<GlProgram>(program_source(shaders_.vertex_vs, defines),
                                             program_source(shaders_.vertex_fs, defines));
  return *facet_draws_.emplace(std::pair{groups, normal_mapped}, std::move(program)).first->second;
}

bool IwasakiCloth::draw_depth(size_t handle, const glm::mat4& view_projection) {
  if (!visible_) return false;
  visible_->draw_depth(objects_.at(handle)->marks, view_projection);
  return true;
}

std::optional<ClothMethod::ShownVertices> IwasakiCloth::shown_vertices(size_t handle) const {
  const Object& o = *objects_.at(handle);
  if (!visible_ || o.shown_stamp == 0) return std::nullopt;
  return ShownVertices{visible_->marks(o.marks), o.shown_stamp};
}

std::vector<float> IwasakiCloth::vertex_values(size_t handle, int* block_texels) const {
  const Object& o = *objects_.at(handle);
  if (!o.pass) return {};
  if (block_texels) *block_texels = o.pass->texels();
  return o.pass->read_values();
}

size_t IwasakiCloth::visible_vertices(size_t handle) const {
  const Object& o = *objects_.at(handle);
  return visible_ && visible_only_ ? visible_->visible(o.marks) : o.vertices;
}

bool IwasakiCloth::has_visibility(size_t handle) const { return objects_.at(handle)->visibility != nullptr; }

void IwasakiCloth::set_fabric(size_t handle, const Fabric& fabric) {
  Object& o = *objects_.at(handle);
  const WeightingTablesTexture& t = tables_for(fabric);
  auto bsdf = std::make_unique<ClothBsdf>(fabric, t.tables().tangent_samples);
  for (int j = 0, s = 0; j < 2; ++j)
    for (int k = 0; k < bsdf->sample_count(j); ++k, ++s)
      if (std::abs(bsdf->tilt(j, k) - t.tables().tilts[s]) > 1e-9)
        throw GpuError("method iwasaki: the tables of fabric '" + fabric.name + "' were baked for other tangent samples");
  const bool colour_only = o.bsdf && same_but_albedo(o.bsdf->fabric(), fabric) && !pass_holds_albedo(shaders_);
  o.bsdf = std::move(bsdf);
  o.ratio_bsdf = std::make_unique<ClothBsdf>(normal_map_ratio_bsdf(*o.bsdf));
  o.tables = &t;
  if (o.pass && !colour_only) o.pass->invalidate();
}

bool IwasakiCloth::set_thread_maps(size_t handle, const ThreadMaps& maps) {
  Object& o = *objects_.at(handle);
  if (!shaders_.thread_maps) return false;
  o.maps = maps;
  return true;
}

bool IwasakiCloth::draws_normal_maps() const {
  // Per vertex, the draw that cuts each SG by the facet applies the map (vertex_normal_map.glsl).
  return shaders_.thread_maps && shaders_.normal_maps && (evaluation_ == Evaluation::per_pixel || shaders_.facet_per_sg);
}

void IwasakiCloth::refresh_all() {
  for (auto& o : objects_)
    if (o->pass) o->pass->invalidate();
}

void IwasakiCloth::draw(size_t handle, const glm::mat4& vp, const glm::vec3& eye, const SgLighting& sgs) {
  Object& o = *objects_.at(handle);
  if (sgs.size() > kMaxSgs) throw GpuError("at most " + std::to_string(kMaxSgs) + " SGs, got " + std::to_string(sgs.size()));
  const SgLighting drawn = shaded(sgs);
  if (o.visibility && !same_lighting(o.computed_for, drawn)) {  // lighting-only work, when it changes
    const SgVisibility values = values_for(o, drawn);
    o.sg_visibility->upload(values);
    if (o.broad_mask) o.broad_bits->upload(values.broad);
    o.computed_for = drawn;
  }
  if (o.pass && !identical_lighting(o.passed_for, drawn)) {
    o.pass->invalidate();
    o.passed_for = drawn;
  }
  const WeightingTables& t = o.tables->tables();
  // Lighting-only work, once per draw on the CPU: σ_k and the λ levels of each SG.
  std::vector<float> axes, amplitudes, sigmas, sharpness, level_w;
  std::vector<GLint> levels;
  for (const auto& g : drawn) {
    axes.insert(axes.end(), {float(g.axis.x), float(g.axis.y), float(g.axis.z)});
    amplitudes.insert(amplitudes.end(), {float(g.amplitude.r), float(g.amplitude.g), float(g.amplitude.b)});
    sigmas.push_back(float(sg_bandwidth(g.sharpness)));
    sharpness.push_back(float(g.sharpness));
    int l0 = 0, l1 = 0;
    double f = 0;
    t.level_weights(g.sharpness, l0, l1, f);
    levels.insert(levels.end(), {l0, l1});
    level_w.push_back(float(f));
  }
  // Per SG: 0 for iwasaki, slot + 1 for the broad lobes' quadrature.
  std::vector<GLint> broad(drawn.size(), 0);
  if (shaders_.broad_lobe_quadrature) {
    const std::vector<int> slots = broad_lobe_slots(drawn);
    for (size_t k = 0; k < drawn.size(); ++k) broad[k] = slots[k] + 1;
  }
  const int count = int(drawn.size());
  // Everything a program built on iwasaki.glsl reads (the cloth's draw or the vertex pass).
  auto set_up = [&](const GlProgram& p) {
    p.use();
    glUniformMatrix4fv(p.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
    glUniform3f(p.uniform("u_eye"), eye.x, eye.y, eye.z);
    upload_fabric(p, *o.bsdf);
    o.tables->bind(p, 0);
    glUniform1i(p.uniform("u_sg_count"), count);
    if (count > 0) {
      glUniform3fv(p.uniform("u_sg_axis"), count, axes.data());
      glUniform3fv(p.uniform("u_sg_amplitude"), count, amplitudes.data());
      glUniform1fv(p.uniform("u_sg_sigma"), count, sigmas.data());
      glUniform1fv(p.uniform("u_sg_sharpness"), count, sharpness.data());
      glUniform2iv(p.uniform("u_sg_levels"), count, levels.data());
      glUniform1fv(p.uniform("u_sg_level_w"), count, level_w.data());
      glUniform1iv(p.uniform("u_sg_broad"), count, broad.data());
    }
    glUniform1i(p.uniform("u_visibility"), o.visibility ? 1 : 0);
    glUniform1i(p.uniform("u_visibility_open_share"), o.mask ? 1 : 0);
    if (shaders_.upload) shaders_.upload(p, o.bsdf->fabric(), drawn);
    // Samplers of every declared unit get a texture of their type, used or not.
    if (o.sg_visibility) o.sg_visibility->bind(p, 2);
    if (kappa_) kappa_->bind(p, 3);
    if (!o.sg_visibility) glUniform1i(p.uniform("u_sg_visibility"), 2);
    if (!kappa_) glUniform1i(p.uniform("u_kappa"), 3);
    if (o.broad_bits) o.broad_bits->bind(p, 7);
    bind_thread_maps(p, o.maps, white_.id(), 9);
  };
  if (broad_pass_) {  // per pixel: the broad lobes' part per vertex first (units 4–6: the pass's inputs)
    set_up(*broad_pass_);
    glUniform1i(broad_pass_->uniform("u_pass_narrow"), 0);
    o.pass->run_share(*broad_pass_, 4, 3, std::max(vertex_shares_, broad_shares_));  // the split's three parts
  }
  set_up(program_);
  if (!o.pass) {
    o.mesh.draw();
    return;
  }
  if (broad_pass_) {
    o.pass->bind_result(program_, 8);
    o.mesh.draw();
    return;
  }
  glUniform1i(program_.uniform("u_pass_narrow"), 1);
  if (!shaders_.facet_per_sg) {
    o.pass->run_share(program_, 4, 1, vertex_shares_);
    draw_program_->use();
    glUniformMatrix4fv(draw_program_->uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
    o.pass->bind_result(*draw_program_, 0);
    o.mesh.draw();
    return;
  }
  // One block of the pass per SG; the draw sums them, each cut by the facet's plane.
  std::vector<int> shares(size_t(std::max(count, 1)), vertex_shares_);
  for (int k = 0; k < count; ++k)
    if (broad[size_t(k)] != 0) shares[size_t(k)] = std::max(vertex_shares_, broad_shares_);
  if (visible_ && visible_only_) {
    visible_->mark_for(*o.pass, o.marks, vp);
    o.shown_stamp = visible_->stamp();
  } else {
    o.pass->clear_marks();
    o.shown_stamp = 0;
  }
  std::vector<const GlProgram*> programs(shares.size(), &program_);
  if (narrow_pass_) {
    set_up(*narrow_pass_);
    for (int k = 0; k < count; ++k)
      if (broad[size_t(k)] == 0) programs[size_t(k)] = narrow_pass_.get();
  }
  o.pass->set_clock(clock_);
  o.pass->run_shares(programs, 4, shares);
  const bool normal_mapped = o.maps.normal_texture != 0;
  const GlProgram& d = facet_draw(count, normal_mapped);
  d.use();
  glUniformMatrix4fv(d.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
  glUniform3f(d.uniform("u_eye"), eye.x, eye.y, eye.z);
  glUniform1i(d.uniform("u_sg_count"), count);
  if (count > 0) {
    glUniform3fv(d.uniform("u_sg_axis"), count, axes.data());
    glUniform1fv(d.uniform("u_sg_sharpness"), count, sharpness.data());
    std::vector<float> terms;
    for (const auto& g : drawn) {
      const SgHemisphereTerms h = sg_hemisphere_terms(g.sharpness);
      terms.insert(terms.end(), {float(h.steepness), float(h.inverse_erf), float(h.exp_minus_lambda)});
    }
    glUniform3fv(d.uniform("u_sg_hemisphere_terms"), count, terms.data());
    glUniform1iv(d.uniform("u_sg_broad"), count, broad.data());
    glUniform3fv(d.uniform("u_sg_amplitude"), count, amplitudes.data());
  }
  if (normal_mapped) {  // the map's ratio: only that draw has its uniforms
    std::vector<float> widen2;
    for (const auto& g : drawn) widen2.push_back(float(weave_lobe_widening(g.sharpness)));
    if (count > 0) glUniform1fv(d.uniform("u_sg_widen2"), count, widen2.data());
    upload_fabric(d, *o.ratio_bsdf);
  }
  float albedo[6];
  for (int j = 0; j < 2; ++j)
    for (int c = 0; c < 3; ++c) albedo[3 * j + c] = float(o.bsdf->fabric().threads[j].albedo[c]);
  glUniform3fv(d.uniform("u_thread_albedo"), 2, albedo);
  bind_thread_maps(d, o.maps, white_.id(), 9);
  o.pass->bind_result(d, 0);
  o.pass->bind_history(d, 8);
  o.mesh.draw();
}

}  // namespace weft::gpu
