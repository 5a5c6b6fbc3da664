#include "gpu/scene_renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gpu/egl_context.h"
#include "gpu/fabric_uniforms.h"
#include "shaders/embedded_shaders.h"

namespace weft::gpu {

namespace {
constexpr int kMaxSgs = 40;  // MAX_SGS in sgpoint.frag

std::string program_source(std::initializer_list<std::string_view> parts) {
  std::string s = shader_preamble();
  for (auto p : parts) s += shaders::source(p);
  return s;
}

const char* kFullscreenVs = R"(#version 300 es
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  gl_Position = vec4(p, 0.0, 1.0);
})";
}  // namespace

Method parse_method(const std::string& name) {
  if (name == "sgpoint") return Method::sgpoint;
  if (name == "iwasaki") return Method::iwasaki;
  throw std::invalid_argument("unknown GPU method '" + name + "' (available: sgpoint, iwasaki)");
}

struct SceneRenderer::Object {
  const SceneObject* source;
  GpuMesh mesh;
  std::unique_ptr<ClothBsdf> bsdf;  // cloth only
  size_t iwasaki = 0;               // handle in iwasaki_ (Method::iwasaki cloth)
};

SceneRenderer::SceneRenderer(const Scene& scene, std::vector<Fabric> fabrics, Method method, int tangent_samples,
                             std::shared_ptr<const IwasakiBundleData> iwasaki)
    : tangent_samples_(tangent_samples) {
  if (method == Method::iwasaki) iwasaki_ = std::make_unique<IwasakiCloth>(std::move(iwasaki));
  cloth_program_ = std::make_unique<GlProgram>(program_source({"scene.vert"}),
                                               program_source({"microcylinder.glsl", "sgpoint.frag"}));
  lambert_program_ = std::make_unique<GlProgram>(program_source({"scene.vert"}), program_source({"lambert.frag"}));
  size_t cloth = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    auto obj = std::make_unique<Object>(Object{&o, GpuMesh(o.mesh), nullptr});
    if (o.material == Material::cloth) {
      if (cloth >= fabrics.size()) throw GpuError("no fabric given for cloth object '" + o.name + "'");
      obj->bsdf = std::make_unique<ClothBsdf>(fabrics[cloth], tangent_samples_);
      if (iwasaki_) obj->iwasaki = iwasaki_->add_object(i, o.mesh, fabrics[cloth]);
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
      o->bsdf = std::make_unique<ClothBsdf>(fabric, tangent_samples_);
      return;
    }
  throw GpuError("no cloth object #" + std::to_string(cloth_index));
}

void SceneRenderer::set_lighting(const SgLighting& sgs) {
  if (sgs.size() > kMaxSgs) throw GpuError("at most " + std::to_string(kMaxSgs) + " SGs, got " + std::to_string(sgs.size()));
  sgs_ = sgs;
  // Lambertian surfaces: SG irradiance per vertex, once per lighting change.
  for (auto& o : objects_) {
    if (o->bsdf) continue;
    const auto& m = o->source->mesh;
    std::vector<glm::vec3> e(m.positions.size());
    for (size_t i = 0; i < e.size(); ++i) {
      glm::dvec3 sum(0.0);
      for (const auto& g : sgs_) sum += irradiance(g, m.normals[i]);
      e[i] = glm::vec3(sum);
    }
    o->mesh.set_vertex_colours(e);
  }
}

void SceneRenderer::draw(const Camera& camera, int width, int height) {
  const glm::mat4 proj = glm::perspective(float(glm::radians(camera.fov_deg)), float(width) / height, 0.05f, 100.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(camera.position), glm::vec3(camera.target), glm::vec3(camera.up));
  const glm::mat4 vp = proj * view;
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  std::vector<float> axes, powers;
  for (const auto& g : sgs_) {
    const glm::dvec3 p = integral(g);  // all of the SG's power along its axis
    axes.insert(axes.end(), {float(g.axis.x), float(g.axis.y), float(g.axis.z)});
    powers.insert(powers.end(), {float(p.r), float(p.g), float(p.b)});
  }
  for (auto& o : objects_) {
    if (o->bsdf && iwasaki_) {
      iwasaki_->draw(o->iwasaki, vp, glm::vec3(camera.position), sgs_);
      continue;
    }
    const GlProgram& prog = o->bsdf ? *cloth_program_ : *lambert_program_;
    prog.use();
    glUniformMatrix4fv(prog.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
    if (o->bsdf) {
      upload_fabric(prog, *o->bsdf);
      glUniform3f(prog.uniform("u_eye"), float(camera.position.x), float(camera.position.y), float(camera.position.z));
      glUniform1i(prog.uniform("u_sg_count"), int(sgs_.size()));
      if (!sgs_.empty()) {
        glUniform3fv(prog.uniform("u_sg_axis"), GLsizei(sgs_.size()), axes.data());
        glUniform3fv(prog.uniform("u_sg_power"), GLsizei(sgs_.size()), powers.data());
      }
    } else {
      const glm::dvec3 a = o->source->albedo;
      glUniform3f(prog.uniform("u_albedo"), float(a.r), float(a.g), float(a.b));
    }
    o->mesh.draw();
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

ToneMapper::ToneMapper() : program_(kFullscreenVs, shader_preamble() + std::string(shaders::source("tonemap.frag"))) {}

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
