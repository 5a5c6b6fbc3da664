#include "gpu/scene_renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <algorithm>
#include <limits>
#include <stdexcept>

#include "gl/frame_profile.h"
#include "gpu/backdrop_cube.h"
#include "gpu/egl_context.h"
#include "image/tone_map.h"
#include "methods/fabric_uniforms.h"
#include "methods/lambert_visibility.h"
#include "methods/program_cloth.h"
#include "methods/sg_lighting_uniforms.h"
#include "methods/weave/weave_layer.h"
#include "scene/weave_scale.h"
#include "shaders/embedded_shaders.h"
#include "scene/bounds.h"

namespace weft::gpu {

namespace {
// The layer's terms for the method (SceneRenderer::set_weave_pixel_terms). Over a per-pixel
// approximation of the model (`sheen`, `sgpoint`) its level is the pixel's own, which a level
// interpolated from the vertices would miscorrect: the table, whose ratio divides out its own
// interpolation.
WeaveLayer::Terms weave_terms(const ClothMethod& cloth, const methods::RuntimeMethod& method, bool pixel_terms) {
  if (cloth.weave_terms_per_pixel()) return WeaveLayer::Terms::pixel;
  if (pixel_terms && method.shading == methods::Shading::per_vertex) return WeaveLayer::Terms::pixel_over_vertex;
  return WeaveLayer::Terms::vertex_table;
}
}  // namespace

SgLighting softened_environment(const SgLighting& sgs, double blur_sharpness) {
  SgLighting out = sgs;
  for (SphericalGaussian& g : out) {
    const double l = g.sharpness, lb = blur_sharpness, ls = l * lb / (l + lb);
    g.amplitude *= sg_sphere_integral(l) / sg_sphere_integral(ls);
    g.sharpness = ls;
  }
  return out;
}

bool is_cloth_alpha(float alpha) { return alpha > 0.0f; }

struct SceneRenderer::Object {
  const SceneObject* source;
  std::unique_ptr<GpuMesh> mesh;  // Lambertian objects; the method's GPU side holds the cloth's
  bool cloth = false;
  size_t handle = 0;  // the cloth's handle in cloth_
  Fabric fabric;      // the cloth's, as drawn (knob edits included)
  bool woven = false;  // cloth with UVs: the weave layer holds it (weave_handle)
  size_t weave_handle = 0;
  bool weave_reachable = false;  // woven, and (set_weave_range) some camera of the range can show its weave
  const ObjectVisibility* lambert_visibility = nullptr;  // Lambertian objects the bundle baked
  // The cloth's baked visibility, for the weave layer's lights (null: none baked).
  const ObjectVisibility* sdf = nullptr;
  const VisibilityMask* mask = nullptr;
};

ShadingParts frame_bake_reads(const methods::RuntimeMethod& method) {
  return method.bake_reads() | ShadingParts{.tables = false, .visibility = true, .masks = true};
}

SceneRenderer::SceneRenderer(const Scene& scene, std::vector<Fabric> fabrics, const methods::RuntimeMethod& method,
                             int tangent_samples,
                             std::shared_ptr<const ShadingData> shading, TableSource tables)
    : method_(&method), bundle_(shading) {
  cloth_ = method.make_gpu(ClothMethodSetup{tangent_samples, std::move(shading), std::move(tables)});
  background_program_ =
      std::make_unique<GlProgram>(fullscreen_triangle_vs(), program_source({"erf.glsl", "sg_lighting.glsl", "background.frag"}));
  lambert_program_ = std::make_unique<GlProgram>(program_source({"scene.vert"}), program_source({"lambert.frag"}));
  size_t cloth = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    auto obj = std::make_unique<Object>();
    obj->source = &o;
    obj->cloth = o.is_cloth();
    // A cloth mesh without UVs has no place for its threads: the fabric level alone.
    obj->woven = obj->cloth && !o.mesh.uvs.empty() && o.mesh.uvs.size() == o.mesh.positions.size();
    obj->weave_reachable = obj->woven;
    if (obj->cloth) {
      if (cloth >= fabrics.size()) throw GpuError("no fabric given for cloth object '" + o.name + "'");
      obj->fabric = object_fabric(o, fabrics[cloth]);
      obj->handle = cloth_->add_object(i, o.mesh, obj->fabric);
      if (bundle_) {
        // Optional for the layer: what was baked for another mesh is left out (the method's own
        // checks name the mismatch where it needs the data).
        const size_t vertices = o.mesh.positions.size();
        const auto v = bundle_->visibility.find(i);
        if (v != bundle_->visibility.end() && v->second.vertex_count() == vertices) obj->sdf = &v->second;
        const auto m = bundle_->masks.find(i);
        if (m != bundle_->masks.end() && m->second.vertex_count() == vertices) obj->mask = &m->second;
      }
      if (o.textured() || o.normal_map) {
        const ThreadMaps maps = thread_maps_of(
            o,
            [&](const TextureImage& image) {
              auto& t = textures_[&image];
              if (!t) t = std::make_unique<ThreadMapTexture>(image);
              return t->id();
            },
            [&](const TextureImage& image) {
              auto& t = normal_textures_[&image];
              if (!t) t = std::make_unique<NormalMapTexture>(image);
              return t->id();
            });
        const bool drawn = cloth_->set_thread_maps(obj->handle, maps);
        if (!drawn && o.textured())
          warnings_.push_back("method " + method.name + " draws cloth object '" + o.name +
                              "' without its texture (the iwasaki rungs and sheen draw it)");
        if (o.normal_map && !(drawn && cloth_->draws_normal_maps()))
          warnings_.push_back("method " + method.name + " ignores the normal map of cloth object '" + o.name +
                              "' (the iwasaki rungs and sheen draw it)");
      }
      ++cloth;
    } else {
      obj->mesh = std::make_unique<GpuMesh>(o.mesh);
      if (bundle_) obj->lambert_visibility = checked_visibility(*bundle_, i, o.mesh);
    }
    objects_.push_back(std::move(obj));
  }
  Bounds all;
  for (const auto& o : scene.objects) all.add(o.mesh.positions);
  if (!all.empty()) bounds_centre_ = all.centre(), bounds_radius_ = 0.5 * glm::length(all.extent());
}

SceneRenderer::~SceneRenderer() = default;

void SceneRenderer::set_fabric(size_t cloth_index, const Fabric& fabric) {
  size_t cloth = 0;
  for (auto& o : objects_)
    if (o->cloth && cloth++ == cloth_index) {
      const Fabric drawn = object_fabric(*o->source, fabric);
      cloth_->set_fabric(o->handle, drawn);  // throws (and changes nothing) for a fabric the method cannot show
      o->fabric = drawn;
      if (weave_ && o->woven) weave_->set_fabric(o->weave_handle, drawn, weave_coordinates(*o->source, drawn));
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
  out.weave.resize(objects_.size());
  const SigmoidGainTable* kappa = bundle_ && bundle_->kappa ? &*bundle_->kappa : nullptr;
  for (size_t k = 0; k < objects_.size(); ++k) {
    const Object& o = *objects_[k];
    if (o.cloth) {
      out.cloth[k] = cloth_->prepare_lighting(o.handle, sgs);
      if (weave_on_ && o.weave_reachable) out.weave[k] = weave_lighting_of(o, sgs);
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
  backdrop_sgs_ = softened_environment(sgs_);
  if (backdrop_cube_) backdrop_cube_->fill(backdrop_sgs_);
  for (size_t k = 0; k < objects_.size(); ++k) {
    Object& o = *objects_[k];
    if (!o.cloth) {
      o.mesh->set_vertex_colours(lighting.irradiance[k]);
      continue;
    }
    if (lighting.cloth[k]) cloth_->set_lighting(o.handle, sgs_, *lighting.cloth[k]);
    if (weave_on_ && o.weave_reachable)
      weave_->set_lighting(o.weave_handle, lighting.weave.size() > k && lighting.weave[k] ? *lighting.weave[k] : weave_lighting_of(o, sgs_));
  }
}

WeaveLighting SceneRenderer::weave_lighting_of(const Object& o, const SgLighting& sgs) const {
  return weave_lighting(sgs, weave_max_lights_, o.mask, o.sdf, o.source->mesh);
}

void SceneRenderer::set_lighting(const SgLighting& sgs) { set_lighting(prepare_lighting(sgs)); }

void SceneRenderer::set_backdrop(Backdrop backdrop) {
  backdrop_ = backdrop;
  if (backdrop_ == Backdrop::showroom && !backdrop_cube_) {
    backdrop_cube_ = std::make_unique<BackdropCube>();
    backdrop_cube_->fill(backdrop_sgs_);
  }
}

std::vector<float> SceneRenderer::cloth_vertex_values(size_t cloth_index, int* block_texels) const {
  size_t n = 0;
  for (const auto& o : objects_)
    if (o->cloth && n++ == cloth_index) return cloth_->vertex_values(o->handle, block_texels);
  throw std::out_of_range("no cloth object " + std::to_string(cloth_index));
}

void SceneRenderer::set_vertex_refresh(int shares) {
  cloth_->set_vertex_refresh(shares);
  vertex_refresh_ = shares;
  if (weave_) weave_->set_vertex_refresh(shares);
}

void SceneRenderer::refresh_all() {
  cloth_->refresh_all();
  if (weave_) weave_->refresh_all();
}

void SceneRenderer::set_visible_vertices_only(bool on) {
  visible_only_ = on;
  cloth_->set_visible_vertices_only(on);
  if (weave_) weave_->set_visible_vertices_only(on);
}

void SceneRenderer::set_weave(bool on) {
  if (on && !weave_) {
    auto layer = std::make_unique<WeaveLayer>();
    layer->set_visible_vertices_only(visible_only_);
    layer->set_vertex_refresh(vertex_refresh_);
    layer->set_terms(weave_terms(*cloth_, *method_, weave_pixel_terms_));
    weave_max_lights_ = layer->max_lights();
    for (auto& o : objects_)
      if (o->woven) o->weave_handle = layer->add_object(o->source->mesh, o->fabric, weave_coordinates(*o->source, o->fabric));
    weave_ = std::move(layer);
  }
  // The lights as they are now: set_lighting leaves the layer's alone while it is off.
  if (on && !weave_on_)
    for (auto& o : objects_)
      if (o->cloth && o->weave_reachable) weave_->set_lighting(o->weave_handle, weave_lighting_of(*o, sgs_));
  weave_on_ = on;
}

void SceneRenderer::set_weave_pixel_terms(bool on) {
  if (on == weave_pixel_terms_) return;
  weave_pixel_terms_ = on;
  if (!weave_) return;
  weave_->set_terms(weave_terms(*cloth_, *method_, weave_pixel_terms_));
  weave_->refresh_all();  // the other terms' kept values are of frames before
}

size_t SceneRenderer::set_weave_range(std::span<const OrbitingCamera> cameras, int width, int height) {
  if (!weave_) return 0;
  size_t reachable = 0;
  for (auto& o : objects_) {
    if (!o->woven) continue;
    const bool was = o->weave_reachable;
    o->weave_reachable = false;
    for (const OrbitingCamera& c : cameras)
      if (weave_->reach(o->weave_handle).nearest_footprint_orbiting(c.camera.position, c.pivot,
                                                                    weave_view(c.camera, width, height).corner_pixel) <
          kWeaveRangeMargin * kWeaveCoarseFootprint) {
        o->weave_reachable = true;
        break;
      }
    reachable += o->weave_reachable;
    // Now in range: its lights as they are (the next lighting change keeps them).
    if (o->weave_reachable && !was && weave_on_) weave_->set_lighting(o->weave_handle, weave_lighting_of(*o, sgs_));
  }
  return reachable;
}

size_t SceneRenderer::shadowed_lambertian_objects() const {
  return size_t(std::count_if(objects_.begin(), objects_.end(), [](const auto& o) { return o->lambert_visibility != nullptr; }));
}

void SceneRenderer::draw(const Camera& camera, int width, int height) {
  // A close-up (a camera nearer its target than 0.2 m) moves the near plane in with it; the far
  // plane lies past the scene's bounds (100 m at least), and a camera outside them moves the near
  // plane out to half the way to them, so that depth keeps its precision at any scale.
  const double to_centre = glm::length(bounds_centre_ - camera.position);
  const float near = float(std::max(double(std::min(0.05f, 0.25f * float(glm::length(camera.target - camera.position)))),
                                    0.5 * (to_centre - bounds_radius_)));
  const float far = float(std::max(100.0, 1.05 * (to_centre + bounds_radius_)));
  const glm::mat4 proj = glm::perspective(float(glm::radians(camera.fov_deg)), float(width) / height, near, far);
  const glm::mat4 view = glm::lookAt(glm::vec3(camera.position), glm::vec3(camera.target), glm::vec3(camera.up));
  const glm::mat4 vp = proj * view;
  const bool see_through = method_->see_through;
  glViewport(0, 0, width, height);
  weave_drawn_ = false;
  glDisable(GL_BLEND);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // Only cloth writes alpha (is_cloth_alpha): the backdrop and Lambertian surfaces leave it 0.
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  glEnable(GL_DEPTH_TEST);

  // The backdrop after the opaque surfaces, at the far plane behind them (depth test ≤ 1 against
  // the cleared depth): only the pixels nothing covers pay for it; see-through cloth blends over it.
  auto draw_backdrop = [&] {
    if (backdrop_ != Backdrop::showroom && !see_through) return;
    const StageScope stage(Stage::backdrop);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glDepthRangef(1.0f, 1.0f);
    glDepthMask(GL_FALSE);
    if (backdrop_ == Backdrop::showroom) {
      backdrop_cube_->draw(glm::inverse(vp), width, height);
    } else {  // the environment exactly, as the reference sees it
      background_program_->use();
      upload_sg_lighting(*background_program_, sgs_);
      const glm::mat4 inv = glm::inverse(vp);
      glUniformMatrix4fv(background_program_->uniform("u_inverse_view_projection"), 1, GL_FALSE, glm::value_ptr(inv));
      glUniform2f(background_program_->uniform("u_viewport"), float(width), float(height));
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDepthMask(GL_TRUE);
    glDepthRangef(0.0f, 1.0f);
    glDepthFunc(GL_LESS);
  };

  // Opaque cloth's depth first where its method can write it (a hair behind itself): the cloth is
  // then shaded about once per pixel, not once per layer drawn back to front, and the frame is the
  // same (ClothMethod::draw_depth).
  if (!see_through && depth_prepass_) {
    const StageScope stage(Stage::cloth);
    for (auto& o : objects_)
      if (o->cloth) cloth_->draw_depth(o->handle, vp);
  }
  // Opaque surfaces first; see-through cloth last, blended over them without writing depth.
  for (int pass = 0; pass < 2; ++pass) {
    for (auto& o : objects_) {
      const bool blended = o->cloth && see_through;
      if (blended != (pass == 1)) continue;
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, o->cloth ? GL_TRUE : GL_FALSE);
      if (blended) {
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ONE, GL_ONE);
        glDepthMask(GL_FALSE);
      }
      if (o->cloth) {
        const StageScope stage(Stage::cloth);
        cloth_->draw(o->handle, vp, glm::vec3(camera.position), sgs_);
      } else {
        const StageScope stage(Stage::surfaces);
        lambert_program_->use();
        glUniformMatrix4fv(lambert_program_->uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
        const glm::dvec3 a = o->source->albedo;
        glUniform3f(lambert_program_->uniform("u_albedo"), float(a.r), float(a.g), float(a.b));
        o->mesh->draw();
      }
      if (blended) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
      }
    }
    if (pass == 0 && weave_on_ && !see_through) {
      const WeaveView view = weave_view(camera, width, height);
      for (auto& o : objects_)
        if (o->cloth && o->weave_reachable && weave_->resolves(o->weave_handle, view)) {
          const StageScope stage(Stage::weave);
          weave_drawn_ = true;
          weave_->draw(o->weave_handle, vp, glm::vec3(camera.position), cloth_->shown_vertices(o->handle));
        }
    }
    if (pass == 0) draw_backdrop();
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
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

ToneMapper::ToneMapper()
    : program_(fullscreen_triangle_vs(), shader_preamble() + tone_map_glsl_defines() + std::string(shaders::source("tonemap.frag"))) {}

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
