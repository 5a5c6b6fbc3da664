#include "methods/program_cloth.h"

#include <glm/gtc/type_ptr.hpp>

#include "methods/fabric_uniforms.h"
#include "shaders/embedded_shaders.h"

namespace weft::gpu {

std::string program_source(const std::vector<std::string_view>& parts, const std::string& defines) {
  std::string s = shader_preamble() + defines;
  for (auto p : parts) s += shaders::source(p);
  return s;
}

std::vector<std::string_view> with_main(std::vector<std::string_view> parts, std::string_view main) {
  parts.push_back(main);
  return parts;
}

ProgramCloth::ProgramCloth(const std::vector<std::string_view>& fragment, const std::string& defines)
    : program_(program_source({"scene.vert"}), program_source(fragment, defines)) {}

size_t ProgramCloth::add_mesh(const TriangleMesh& mesh) {
  meshes_.emplace_back(mesh);
  if (!mesh.uvs.empty()) {  // scene.vert's a_uv, for a method that reads textures
    std::vector<glm::vec3> uv(mesh.uvs.size());
    for (size_t i = 0; i < uv.size(); ++i) uv[i] = glm::vec3(float(mesh.uvs[i].x), float(mesh.uvs[i].y), 0.0f);
    meshes_.back().add_attribute(6, uv);
  }
  return meshes_.size() - 1;
}

void ProgramCloth::draw(size_t handle, const glm::mat4& view_projection, const glm::vec3& eye, const SgLighting& sgs) {
  program_.use();
  glUniformMatrix4fv(program_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
  glUniform3f(program_.uniform("u_eye"), eye.x, eye.y, eye.z);
  upload(handle, program_, sgs);
  meshes_.at(handle).draw();
}

}  // namespace weft::gpu
