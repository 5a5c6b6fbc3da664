#include "methods/weave/weave_layer.h"

#include <glm/gtc/type_ptr.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "gl/gl_error.h"
#include "methods/fabric_uniforms.h"
#include "methods/program_cloth.h"
#include "methods/sg_lighting_uniforms.h"
#include "methods/sg_lights.h"
#include "methods/weave/weave_float_table.h"
#include "methods/weave/weave_ratio.h"
#include "scene/weave_scale.h"

namespace weft::gpu {

namespace {
constexpr GLuint kStAttribute = 4;  // weave_layer.vert's a_st

// Each a whole vec4 in case the GL packs no tighter. Per-pixel terms: position, normal, warp,
// weave coordinates and a vec4 per group of four lights for their visibility (and the
// fabric-level response over the vertex level). Vertex table: weave coordinates, the fabric-level
// response and the per-float table's RGB values packed four to a vec4, whatever the lights.
constexpr int kTableVec4s = (3 * 2 * kWeaveTableArcs + 3) / 4;
int weave_varying_components(int q_groups, WeaveLayer::Terms terms) {
  switch (terms) {
    case WeaveLayer::Terms::vertex_table: return 4 * (2 + kTableVec4s);
    case WeaveLayer::Terms::pixel_over_vertex: return 20 + 4 * q_groups;
    default: return 16 + 4 * q_groups;
  }
}
int varying_limit() {
  GLint out = 0, in = 0;
  glGetIntegerv(GL_MAX_VERTEX_OUTPUT_COMPONENTS, &out);
  glGetIntegerv(GL_MAX_FRAGMENT_INPUT_COMPONENTS, &in);
  return std::min(out, in);
}
constexpr int kMaxCurvePoints = 16;  // MAX_CURVE_POINTS in weave_layout.glsl
constexpr int kTermsUnit = 3;        // the vertex pass's result, above its inputs (0–2)
constexpr int kTableUnit = 4;        // the table pass's result
constexpr int kReachUnit = 5, kReachBeforeUnit = 7;
constexpr int kVisibilityUnit = 6;
constexpr int kVisibilityWidth = 1024;

}  // namespace

void upload_weave_layout(const GlProgram& p, const WeaveLayout& layout, const Fabric& fabric) {
  glUniform1i(p.uniform("u_weave_rows"), layout.rows());
  glUniform1i(p.uniform("u_weave_shift"), layout.shift());
  glUniform1f(p.uniform("u_weave_warp_share"), float(layout.warp_share()));
  glUniform1f(p.uniform("u_weave_width"), float(layout.yarn_width()));
  std::vector<float> tilts(2 * kMaxCurvePoints, 0.0f), arcs(2 * kMaxCurvePoints, 0.0f);
  GLint points[2];
  for (int j = 0; j < 2; ++j) {
    const TangentCurve& c = fabric.threads[j].curve;
    points[j] = GLint(c.offsets_deg().size());
    double arc = 0.0;
    for (int i = 0; i < points[j]; ++i) {
      tilts[j * kMaxCurvePoints + i] = float(glm::radians(c.offsets_deg()[i]));
      arcs[j * kMaxCurvePoints + i] = float(arc / c.total_length());
      if (i < int(c.lengths().size())) arc += c.lengths()[i];
    }
  }
  glUniform1iv(p.uniform("u_curve_points"), 2, points);
  glUniform1fv(p.uniform("u_curve_tilts"), 2 * kMaxCurvePoints, tilts.data());
  glUniform1fv(p.uniform("u_curve_arcs"), 2 * kMaxCurvePoints, arcs.data());
}

std::string weave_defines(int q_groups) {
  char floats[96];
  std::snprintf(floats, sizeof floats, "#define RATIO_FLOOR %.9e\n#define RATIO_CAP %.9e\n", kWeaveRatioFloor, kWeaveRatioCap);
  return "#define Q_GROUPS " + std::to_string(q_groups) + "\n#define MAX_SGS " + std::to_string(kMaxSgs) +
         "\n#define WEAVE_TABLE_ARCS " + std::to_string(kWeaveTableArcs) + "\n#define WEAVE_TABLE_NODES " +
         std::to_string(2 * kWeaveTableArcs) + "\n#define WEAVE_TABLE_VEC4S " + std::to_string(kTableVec4s) + "\n" + floats;
}

size_t WeaveLayer::add_object(const TriangleMesh& mesh, const Fabric& fabric, std::vector<glm::dvec2> st) {
  if (mesh.uvs.size() != mesh.positions.size()) throw GpuError("weave layer: a cloth mesh without UVs");
  auto o = std::make_unique<Object>();
  o->source = &mesh;
  o->mesh = std::make_unique<GpuMesh>(mesh);
  objects_.push_back(std::move(o));
  set_fabric(objects_.size() - 1, fabric, std::move(st));
  return objects_.size() - 1;
}

void WeaveLayer::set_fabric(size_t handle, const Fabric& fabric, std::vector<glm::dvec2> st) {
  for (const auto& t : fabric.threads)
    if (t.curve.offsets_deg().size() > size_t(kMaxCurvePoints))
      throw GpuError("weave layer: fabric '" + fabric.name + "' has a tangent curve of more than " +
                     std::to_string(kMaxCurvePoints) + " points");
  Object& o = *objects_.at(handle);
  if (st.size() != o.source->positions.size()) throw GpuError("weave layer: one weave coordinate per vertex needed");
  for (const glm::dvec2& c : st)
    if (!(std::isfinite(c.x) && std::isfinite(c.y))) throw GpuError("weave layer: the weave's coordinates must be finite");
  o.bsdf = std::make_unique<ClothBsdf>(fabric, tangent_samples_);
  if (o.pass) o.pass->invalidate(), o.table->invalidate();  // kept terms are of the fabric before
  auto layout = std::make_unique<WeaveLayout>(fabric);
  const bool resized = st != o.st;
  if (resized) {  // another preset's repeat: its threads at their own size
    std::vector<glm::vec3> attribute(st.size());
    for (size_t i = 0; i < st.size(); ++i) attribute[i] = glm::vec3(st[i], 0.0);
    o.mesh->add_attribute(kStAttribute, attribute);
    o.st = std::move(st);
  }
  if (!o.layout || resized || o.layout->rows() != layout->rows()) o.reach = std::make_unique<WeaveReach>(*o.source, o.st, layout->rows());
  o.layout = std::move(layout);
}

void WeaveLayer::upload_reach(Object& o) {
  const int width = o.pass->width(), rows = o.pass->texels() / width;
  std::vector<float> texels(size_t(width) * rows, 1e30f);  // out of reach until drawn
  auto upload = [&](GlTexture& t) {
    glBindTexture(GL_TEXTURE_2D, t.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, width, rows, 0, GL_RED, GL_FLOAT, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  };
  if (!o.reach_filled) {
    upload(o.reach_texels[0]);
    upload(o.reach_texels[1]);
    o.reach_filled = true;
  }
  std::copy(o.footprints.begin(), o.footprints.end(), texels.begin());
  o.reach_now ^= 1;
  upload(o.reach_texels[o.reach_now]);
  check_gl("uploading the weave layer's reach");
}

void WeaveLayer::refresh_all() {
  for (auto& o : objects_)
    if (o->pass) {
      o->pass->invalidate();
      o->table->invalidate();
    }
}

int WeaveLayer::max_lights() const {
  const int limit = varying_limit();
  int groups = kMaxSgs / 4;
  while (groups > 1 && weave_varying_components(groups, terms_) > limit) --groups;
  return 4 * groups;
}

bool WeaveLayer::resolves(size_t handle, const WeaveView& view) {
  Object& o = *objects_.at(handle);
  return o.reach->footprints(view, kWeaveCoarseFootprint, o.footprints) < kWeaveCoarseFootprint;
}

const WeaveLayer::Programs& WeaveLayer::programs(int q_groups, Terms terms) {
  auto it = programs_.find({q_groups, terms});
  if (it != programs_.end()) return it->second;
  std::string defines = weave_defines(q_groups);
  Programs p;
  const int needed = weave_varying_components(q_groups, terms), limit = varying_limit();
  if (needed > limit)
    throw GpuError("weave layer: " + std::to_string(4 * q_groups) + " lights need " + std::to_string(needed) +
                   " varying components per vertex, more than this GL's " + std::to_string(limit) + ": fit fewer SGs");
  if (terms != Terms::pixel)
    p.pass = std::make_unique<GlProgram>(
        fullscreen_triangle_vs(),
        program_source({"microcylinder.glsl", "vertex_pass.glsl", "erf.glsl", "weave_layout.glsl", "weave_ratio.glsl",
                        "weave_visibility.glsl", "weave_reach.glsl", "weave_vertex_pass.frag"},
                       defines));
  if (terms == Terms::pixel_over_vertex) defines += "#define WEAVE_VERTEX_LEVEL\n";
  if (terms == Terms::vertex_table) {
    p.table = std::make_unique<GlProgram>(
        fullscreen_triangle_vs(),
        program_source({"microcylinder.glsl", "vertex_pass.glsl", "erf.glsl", "weave_layout.glsl", "weave_ratio.glsl",
                        "weave_visibility.glsl", "weave_reach.glsl", "weave_float_table.glsl", "weave_table_pass.frag"},
                       defines));
    defines += "#define WEAVE_VERTEX_TERMS\n";
  }
  p.draw = std::make_unique<GlProgram>(
      program_source({"weave_visibility.glsl", "weave_layer.vert"}, defines),
      program_source({"microcylinder.glsl", "erf.glsl", "weave_layout.glsl", "weave_ratio.glsl", "weave_float_table.glsl",
                      "weave_layer.frag"},
                     defines));
  return programs_.emplace(std::make_pair(q_groups, terms), std::move(p)).first->second;
}

void upload_weave_tilt_spreads(const GlProgram& program, const ClothBsdf& bsdf) {
  std::vector<float> spreads(2 * kMaxTangentSamples, 0.0f);
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < bsdf.sample_count(j); ++k) spreads[j * kMaxTangentSamples + k] = float(bsdf.tilt_spread(j, k));
  glUniform4fv(program.uniform("u_weave_tilt_spreads"), 2 * kMaxTangentSamples / 4, spreads.data());
}

VertexPass& WeaveLayer::vertex_pass(Object& o) {
  if (!o.pass) {
    // The method's pass vertices (pass_of), so the layer's vertex level blends as its shading does.
    o.pass = std::make_unique<VertexPass>(*o.source, pass_of(*o.source));
    o.table = std::make_unique<VertexPass>(*o.source, pass_of(*o.source));
    if (!visible_ && VisibleVertices::supported()) visible_ = std::make_unique<VisibleVertices>();
    if (visible_) o.marks = visible_->add_mesh(*o.source, *o.mesh, o.pass->texels());  // for a method that marks none
  }
  return *o.pass;
}

void WeaveLayer::set_lighting(size_t handle, const WeaveLighting& lighting) {
  Object& o = *objects_.at(handle);
  const SgLighting& lights = lighting.lights;
  if (lights.size() > size_t(max_lights()))
    throw GpuError("weave layer: at most " + std::to_string(max_lights()) + " lights on this GL, got " + std::to_string(lights.size()));
  const size_t vertices = o.source->positions.size();
  if (!lighting.visibility.empty() && lighting.visibility.size() != vertices * lights.size())
    throw GpuError("weave layer: visibility of " + std::to_string(lighting.visibility.size()) + " values for " +
                   std::to_string(vertices) + " vertices × " + std::to_string(lights.size()) + " lights");
  o.lights = lights;
  o.lit = true;
  if (o.pass) o.pass->invalidate(), o.table->invalidate();  // kept terms are of the lights before
  o.occluded = !lighting.visibility.empty();
  if (!o.occluded) return;
  // Group g of vertex v at (v mod W, v div W + g·rows), four lights a texel.
  const int groups = std::max(1, int((lights.size() + 3) / 4));
  o.visibility_width = int(std::min<size_t>(vertices, kVisibilityWidth));
  o.visibility_rows = int((vertices + o.visibility_width - 1) / o.visibility_width);
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (o.visibility_rows * groups > max_size)
    throw GpuError("weave layer: " + std::to_string(vertices) + " vertices × " + std::to_string(lights.size()) +
                   " lights do not fit a " + std::to_string(max_size) + "² texture");
  std::vector<float> texels(size_t(o.visibility_width) * o.visibility_rows * groups * 4, 1.0f);
  for (size_t v = 0; v < vertices; ++v)
    for (size_t k = 0; k < lights.size(); ++k) {
      const size_t x = v % o.visibility_width, y = v / o.visibility_width + (k / 4) * o.visibility_rows;
      texels[(y * o.visibility_width + x) * 4 + k % 4] = lighting.visibility[v * lights.size() + k];
    }
  glBindTexture(GL_TEXTURE_2D, o.visibility.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, o.visibility_width, o.visibility_rows * groups, 0, GL_RGBA, GL_FLOAT, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  check_gl("uploading the weave layer's visibility");
}

void WeaveLayer::draw(size_t handle, const glm::mat4& vp, const glm::vec3& eye, std::optional<ClothMethod::ShownVertices> shown) {
  Object& o = *objects_.at(handle);
  if (!o.lit) throw GpuError("weave layer: drawn before its lighting was set");
  const SgLighting& sgs = o.lights;
  const int groups = std::max(1, int((sgs.size() + 3) / 4));
  const Programs& p = programs(groups, terms_);
  std::vector<float> axes, powers, widen2;
  for (const auto& g : sgs) {
    const glm::dvec3 power = sg_power(g);
    widen2.push_back(float(weave_lobe_widening(g.sharpness)));
    axes.insert(axes.end(), {float(g.axis.x), float(g.axis.y), float(g.axis.z)});
    powers.insert(powers.end(), {float(power.r), float(power.g), float(power.b)});
  }
  auto set_up = [&](const GlProgram& program) {
    program.use();
    glUniform3f(program.uniform("u_eye"), eye.x, eye.y, eye.z);
    upload_fabric(program, *o.bsdf);
    upload_weave_tilt_spreads(program, *o.bsdf);
    upload_weave_layout(program, *o.layout, o.bsdf->fabric());
    glUniform1i(program.uniform("u_sg_count"), GLint(sgs.size()));
    if (!sgs.empty()) {
      glUniform3fv(program.uniform("u_sg_axis"), GLsizei(sgs.size()), axes.data());
      glUniform3fv(program.uniform("u_sg_power"), GLsizei(sgs.size()), powers.data());
      glUniform1fv(program.uniform("u_sg_widen2"), GLsizei(sgs.size()), widen2.data());
    }
    glUniform1i(program.uniform("u_weave_visibility"), o.occluded ? 1 : 0);
    glActiveTexture(GL_TEXTURE0 + kVisibilityUnit);
    glBindTexture(GL_TEXTURE_2D, o.visibility.id());
    glUniform1i(program.uniform("u_weave_visibility_texels"), kVisibilityUnit);
    glUniform1i(program.uniform("u_weave_visibility_width"), o.visibility_width);
    glUniform1i(program.uniform("u_weave_visibility_rows"), o.visibility_rows);
    glActiveTexture(GL_TEXTURE0 + kReachUnit);
    glBindTexture(GL_TEXTURE_2D, o.reach_texels[o.reach_now].id());
    glUniform1i(program.uniform("u_weave_reach"), kReachUnit);
    glActiveTexture(GL_TEXTURE0 + kReachBeforeUnit);
    glBindTexture(GL_TEXTURE_2D, o.reach_texels[o.reach_now ^ 1].id());
    glUniform1i(program.uniform("u_weave_reach_before"), kReachBeforeUnit);
    glUniform1f(program.uniform("u_weave_coarse"), float(kWeaveCoarseFootprint));
  };
  // The method's marks of this view where it made them; else the layer's own.
  auto mark = [&](VertexPass& target) {
    if (!visible_only_ || (!shown && !visible_))
      target.clear_marks();  // culling switched off after frames with it on: every vertex again
    else if (shown)
      target.set_marks(shown->buffer, shown->stamp);
    else
      visible_->mark_for(target, o.marks, vp);
  };
  if (p.pass) {
    VertexPass& pass = vertex_pass(o);
    upload_reach(o);
    set_up(*p.pass);
    mark(pass);
    // Block 0 the fabric level; the Qs' blocks only for the table, whose pass reads them (lit per
    // pixel, the draw takes each pixel's own).
    pass.run_share(*p.pass, 0, p.table ? groups + 1 : 1, shares_);
  }
  if (p.table) {
    VertexPass& pass = *o.pass;
    // Then each float's table from the terms' Qs: a second target, as a pass cannot read its own.
    set_up(*p.table);
    glActiveTexture(GL_TEXTURE0 + kTermsUnit);
    glBindTexture(GL_TEXTURE_2D, pass.result_texture());
    glUniform1i(p.table->uniform("u_weave_terms"), kTermsUnit);
    mark(*o.table);  // the same view: the same marks
    o.table->run_share(*p.table, 0, 2 * kWeaveTableArcs, shares_);
  }
  set_up(*p.draw);
  glUniformMatrix4fv(p.draw->uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
  glUniform2f(p.draw->uniform("u_lod"), float(kWeaveFineFootprint), float(kWeaveCoarseFootprint));
  if (p.pass) o.pass->bind_result(*p.draw, kTermsUnit);
  if (p.table) {
    glActiveTexture(GL_TEXTURE0 + kTableUnit);
    glBindTexture(GL_TEXTURE_2D, o.table->result_texture());
    glUniform1i(p.draw->uniform("u_weave_table"), kTableUnit);
  }
  GLint depth_func = GL_LESS;
  glGetIntegerv(GL_DEPTH_FUNC, &depth_func);
  const GLboolean blend = glIsEnabled(GL_BLEND);
  GLboolean depth_mask = GL_TRUE, colour_mask[4];
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
  glGetBooleanv(GL_COLOR_WRITEMASK, colour_mask);
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  o.mesh->draw();
  glDepthFunc(GLenum(depth_func));
  glDepthMask(depth_mask);
  glColorMask(colour_mask[0], colour_mask[1], colour_mask[2], colour_mask[3]);
  if (!blend) glDisable(GL_BLEND);
  check_gl("drawing the weave layer");
}

}  // namespace weft::gpu
