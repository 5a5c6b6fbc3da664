#include "gpu/scene_renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <algorithm>
#include <stdexcept>

#include "gpu/egl_context.h"
#include "gpu/fabric_uniforms.h"
#include "gpu/method_uniforms.h"
#include "gpu/mizutani_textures.h"
#include "methods/lambert_visibility.h"
#include "runtime/paper_tangent_samples.h"
#include "shaders/embedded_shaders.h"

namespace weft::gpu {

namespace {
// The method table: fragment shader parts in order, and whether the cloth shows what lies
// behind it (drawn last, blended dst·α + src, over the SG environment).
struct MethodInfo {
  Method method;
  const char* name;
  std::vector<std::string_view> fragment;
  bool see_through;
};
const std::vector<MethodInfo>& method_table() {
  static const std::vector<MethodInfo> table = {
      {Method::sgpoint, "sgpoint", {"microcylinder.glsl", "sgpoint.frag"}, false},
      {Method::sheen, "sheen", {"erf.glsl", "sg_lighting.glsl", "sheen.glsl", "sheen.frag"}, false},
      {Method::mdfrot, "mdfrot", {"erf.glsl", "sg_lighting.glsl", "mdfrot.glsl", "mdfrot.frag"}, false},
      {Method::thin, "thin", {"microcylinder.glsl", "erf.glsl", "sg_lighting.glsl", "thin_over_sgpoint.glsl", "thin.glsl", "thin.frag"}, true},
      {Method::mizutani, "mizutani", {"microcylinder.glsl", "hemisphere_grid.glsl", "mizutani.glsl", "mizutani.frag"}, false},
      {Method::iwasaki, "iwasaki", {}, false},  // its own programs: gpu/iwasaki_cloth.h
      {Method::iwasaki_vertex, "iwasaki_vertex", {}, false},
  };
  return table;
}
const MethodInfo& info(Method m) {
  for (const auto& i : method_table())
    if (i.method == m) return i;
  throw std::logic_error("method missing from the method table");
}

std::string program_source(const std::vector<std::string_view>& parts) {
  std::string s = shader_preamble();
  for (auto p : parts) s += shaders::source(p);
  return s;
}

}  // namespace

Method parse_method(const std::string& name) {
  std::string all;
  for (const auto& i : method_table()) {
    if (name == i.name) return i.method;
    all += (all.empty() ? "" : ", ") + std::string(i.name);
  }
  throw std::invalid_argument("unknown GPU method '" + name + "' (available: " + all + ")");
}

std::string method_name(Method method) { return info(method).name; }

bool uses_seed000_tables(Method method) { return method == Method::iwasaki || method == Method::iwasaki_vertex; }
bool reads_seed000_tables(Method method) { return uses_seed000_tables(method) || method == Method::mizutani; }

namespace {
bool named_method_is(const std::string& name, bool (*predicate)(Method)) {
  for (const auto& i : method_table())
    if (name == i.name) return predicate(i.method);
  return false;
}
}  // namespace

bool uses_seed000_tables(const std::string& name) { return named_method_is(name, uses_seed000_tables); }
bool reads_seed000_tables(const std::string& name) { return named_method_is(name, reads_seed000_tables); }

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const auto& i : method_table()) names.push_back(i.name);
  return names;
}

struct SceneRenderer::Object {
  const SceneObject* source;
  GpuMesh mesh;
  std::unique_ptr<ClothBsdf> bsdf;  // cloth only
  SheenParams sheen;
  MdfrotParams mdfrot;
  ThinParams thin;
  void set(const Fabric& f, int tangent_samples) {
    bsdf = std::make_unique<ClothBsdf>(f, tangent_samples);
    sheen = sheen_params(f);
    mdfrot = mdfrot_params(f);
    thin = thin_params(f);
  }
  std::unique_ptr<MizutaniTextures> mizutani;  // cloth under Method::mizutani
  size_t iwasaki = 0;                           // handle in iwasaki_ (Method::iwasaki(_vertex) cloth)
  const ObjectVisibility* lambert_visibility = nullptr;  // Lambertian objects the bundle baked
};

// Method::mizutani runs with the tangent samples of seed 000 Table 1, which its tables are
// baked for; knob edits keep them (the tables depend on the curves, not on A or γ).
std::unique_ptr<ClothBsdf> SceneRenderer::mizutani_cloth(const Fabric& fabric) const {
  return std::make_unique<ClothBsdf>(fabric, paper_tangent_samples(fabric));
}

SceneRenderer::SceneRenderer(const Scene& scene, std::vector<Fabric> fabrics, Method method, int tangent_samples,
                             std::shared_ptr<const IwasakiBundleData> iwasaki,
                             const MizutaniTableSource& mizutani_tables)
    : method_(method), bundle_(iwasaki), tangent_samples_(tangent_samples) {
  if (uses_seed000_tables(method))
    iwasaki_ = std::make_unique<IwasakiCloth>(std::move(iwasaki), method == Method::iwasaki_vertex
                                                                      ? IwasakiCloth::Evaluation::per_vertex
                                                                      : IwasakiCloth::Evaluation::per_pixel);
  std::string fragment = program_source(info(method).fragment);
  if (method == Method::mizutani) {  // its light arrays are sized at compile time
    fragment = program_source({}) + "#define MAX_SGS " + std::to_string(kMizutaniMaxSgs) + "\n" +
               fragment.substr(program_source({}).size());
    if (!mizutani_tables.azimuthal) throw GpuError("mizutani: no azimuthal table (baked offline: weft render, weft bench)");
    azimuthal_ = std::make_unique<AzimuthalTable>(mizutani_tables.azimuthal());
  }
  if (!iwasaki_) cloth_program_ = std::make_unique<GlProgram>(program_source({"scene.vert"}), fragment);
  if (info(method).see_through)
    background_program_ =
        std::make_unique<GlProgram>(fullscreen_triangle_vs(), program_source({"erf.glsl", "sg_lighting.glsl", "background.frag"}));
  lambert_program_ = std::make_unique<GlProgram>(program_source({"scene.vert"}), program_source({"lambert.frag"}));
  size_t cloth = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    auto obj = std::make_unique<Object>(Object{&o, GpuMesh(o.mesh), nullptr, {}, {}, {}, nullptr, 0, nullptr});
    if (o.material != Material::cloth && bundle_) obj->lambert_visibility = checked_visibility(*bundle_, i, o.mesh);
    if (o.material == Material::cloth) {
      if (cloth >= fabrics.size()) throw GpuError("no fabric given for cloth object '" + o.name + "'");
      obj->set(fabrics[cloth], tangent_samples_);
      if (iwasaki_) obj->iwasaki = iwasaki_->add_object(i, o.mesh, fabrics[cloth]);
      if (method == Method::mizutani) {
        obj->bsdf = mizutani_cloth(fabrics[cloth]);
        // Seed 001's W is seed 000's: a bundle's tables serve when baked for the same samples.
        const auto samples = paper_tangent_samples(fabrics[cloth]);
        const WeightingTables* from_bundle = nullptr;
        if (iwasaki)
          if (auto t = iwasaki->tables.find(fabrics[cloth].name); t != iwasaki->tables.end() && t->second.tangent_samples == samples)
            from_bundle = &t->second;
        if (from_bundle) {
          obj->mizutani = std::make_unique<MizutaniTextures>(*from_bundle, *azimuthal_);
        } else {
          if (!mizutani_tables.weighting)
            throw GpuError("mizutani: no weighting tables for " + fabrics[cloth].name + " (baked offline: weft render, weft bench)");
          obj->mizutani = std::make_unique<MizutaniTextures>(mizutani_tables.weighting(fabrics[cloth], samples), *azimuthal_);
        }
      }
      ++cloth;
    }
    objects_.push_back(std::move(obj));
  }
}

SceneRenderer::~SceneRenderer() = default;

void SceneRenderer::set_fabric(size_t cloth_index, const Fabric& fabric) {
  size_t cloth = 0;
  for (auto& o : objects_)
    if (o->bsdf && cloth++ == cloth_index) {
      if (iwasaki_) iwasaki_->set_fabric(o->iwasaki, fabric);  // throws (and changes nothing) without tables
      o->set(fabric, tangent_samples_);
      if (method_ == Method::mizutani) o->bsdf = mizutani_cloth(fabric);
      return;
    }
  throw GpuError("no cloth object #" + std::to_string(cloth_index));
}

SceneRenderer::PreparedLighting SceneRenderer::prepare_lighting(const SgLighting& sgs) const {
  if (sgs.size() > size_t(kMaxSgs)) throw GpuError("at most " + std::to_string(kMaxSgs) + " SGs, got " + std::to_string(sgs.size()));
  PreparedLighting out;
  out.sgs = sgs;
  out.irradiance.resize(objects_.size());
  out.cloth.resize(objects_.size());
  const SigmoidGainTable* kappa = bundle_ && bundle_->kappa ? &*bundle_->kappa : nullptr;
  for (size_t k = 0; k < objects_.size(); ++k) {
    const Object& o = *objects_[k];
    if (o.source->material == Material::cloth) {
      if (iwasaki_) out.cloth[k] = iwasaki_->visibility_for(o.iwasaki, sgs);
      continue;
    }
    const auto& m = o.source->mesh;
    std::optional<SgVisibility> vis;
    if (o.lambert_visibility) vis = SgVisibility::compute(*o.lambert_visibility, m, sgs);
    std::vector<glm::vec3>& e = out.irradiance[k];
    e.resize(m.positions.size());
    for (size_t i = 0; i < e.size(); ++i) {
      const SurfaceFrame f = vis ? SurfaceFrame::from_normal_warp(m.normals[i], m.warps[i]) : SurfaceFrame{m.normals[i], {}, {}};
      e[i] = glm::vec3(lambert_irradiance(sgs, f, vis ? &*vis : nullptr, i, kappa));
    }
  }
  return out;
}

void SceneRenderer::set_lighting(const PreparedLighting& lighting) {
  if (lighting.irradiance.size() != objects_.size() || lighting.cloth.size() != objects_.size())
    throw GpuError("lighting prepared for another scene");
  sgs_ = lighting.sgs;
  for (size_t k = 0; k < objects_.size(); ++k) {
    Object& o = *objects_[k];
    if (o.source->material != Material::cloth)
      o.mesh.set_vertex_colours(lighting.irradiance[k]);
    else if (iwasaki_ && lighting.cloth[k])
      iwasaki_->set_visibility(o.iwasaki, sgs_, *lighting.cloth[k]);
  }
}

void SceneRenderer::set_lighting(const SgLighting& sgs) { set_lighting(prepare_lighting(sgs)); }

size_t SceneRenderer::shadowed_lambertian_objects() const {
  return size_t(std::count_if(objects_.begin(), objects_.end(), [](const auto& o) { return o->lambert_visibility != nullptr; }));
}

void SceneRenderer::draw(const Camera& camera, int width, int height) {
  const glm::mat4 proj = glm::perspective(float(glm::radians(camera.fov_deg)), float(width) / height, 0.05f, 100.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(camera.position), glm::vec3(camera.target), glm::vec3(camera.up));
  const glm::mat4 vp = proj * view;
  const bool see_through = info(method_).see_through;
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (see_through) {  // the environment behind the cloth
    background_program_->use();
    upload_sg_lighting(*background_program_, sgs_);
    const glm::mat4 inv = glm::inverse(vp);
    glUniformMatrix4fv(background_program_->uniform("u_inverse_view_projection"), 1, GL_FALSE, glm::value_ptr(inv));
    glUniform2f(background_program_->uniform("u_viewport"), float(width), float(height));
    glDisable(GL_DEPTH_TEST);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glEnable(GL_DEPTH_TEST);

  std::vector<float> axes, powers;
  for (const auto& g : sgs_) {
    const glm::dvec3 p = integral(g);  // all of the SG's power along its axis
    axes.insert(axes.end(), {float(g.axis.x), float(g.axis.y), float(g.axis.z)});
    powers.insert(powers.end(), {float(p.r), float(p.g), float(p.b)});
  }
  // Opaque surfaces first; see-through cloth last, blended over them without writing depth.
  for (int pass = 0; pass < 2; ++pass) {
    for (auto& o : objects_) {
      const bool blended = o->bsdf && see_through;
      if (blended != (pass == 1)) continue;
      if (o->bsdf && iwasaki_) {
        iwasaki_->draw(o->iwasaki, vp, glm::vec3(camera.position), sgs_);
        continue;
      }
      const GlProgram& prog = o->bsdf ? *cloth_program_ : *lambert_program_;
      prog.use();
      glUniformMatrix4fv(prog.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
      if (o->bsdf) {
        glUniform3f(prog.uniform("u_eye"), float(camera.position.x), float(camera.position.y), float(camera.position.z));
        switch (method_) {
          case Method::sgpoint:
            upload_fabric(prog, *o->bsdf);
            glUniform1i(prog.uniform("u_sg_count"), int(sgs_.size()));
            if (!sgs_.empty()) {
              glUniform3fv(prog.uniform("u_sg_axis"), GLsizei(sgs_.size()), axes.data());
              glUniform3fv(prog.uniform("u_sg_power"), GLsizei(sgs_.size()), powers.data());
            }
            break;
          case Method::sheen:
            upload_sg_lighting(prog, sgs_);
            upload_sheen(prog, o->sheen);
            break;
          case Method::mdfrot:
            upload_sg_lighting(prog, sgs_);
            upload_mdfrot(prog, o->mdfrot);
            break;
          case Method::thin:
            upload_fabric(prog, *o->bsdf);
            upload_sg_lighting(prog, sgs_);
            upload_thin(prog, o->thin);
            break;
          case Method::iwasaki:  // drawn by iwasaki_ above
          case Method::iwasaki_vertex:
            break;
          case Method::mizutani:
            upload_fabric(prog, *o->bsdf);
            o->mizutani->bind(prog);
            upload_mizutani_lights(prog, sgs_);
            break;
        }
      } else {
        const glm::dvec3 a = o->source->albedo;
        glUniform3f(prog.uniform("u_albedo"), float(a.r), float(a.g), float(a.b));
      }
      if (blended) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_SRC_ALPHA);
        glDepthMask(GL_FALSE);
      }
      o->mesh.draw();
      if (blended) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
      }
    }
  }
}

Image read_linear_image(int width, int height) {
  std::vector<float> px(size_t(width) * height * 4);
  glFinish();
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, px.data());
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* p = &px[(size_t(height - 1 - y) * width + x) * 4];
      img.at(x, y) = glm::dvec3(p[0], p[1], p[2]);
    }
  return img;
}

ToneMapper::ToneMapper() : program_(fullscreen_triangle_vs(), shader_preamble() + std::string(shaders::source("tonemap.frag"))) {}

void ToneMapper::draw(GLuint linear_texture, float exposure) const {
  program_.use();
  glDisable(GL_DEPTH_TEST);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, linear_texture);
  glUniform1i(program_.uniform("u_linear"), 0);
  glUniform1f(program_.uniform("u_exposure"), exposure);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace weft::gpu
