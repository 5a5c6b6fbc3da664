#pragma once
// The GPU side of a method drawn with one program over the scene mesh (shaders/scene.vert and
// the method's fragment parts): it keeps the meshes and the program and sets the view; the
// method adds its per-object state and uniforms.
#include <string>
#include <string_view>
#include <vector>

#include "gl/gl_program.h"
#include "gl/gpu_mesh.h"
#include "methods/cloth_method.h"

namespace weft::gpu {

class ProgramCloth : public ClothMethod {
public:
  // `fragment`: embedded shader names, after the preamble and `defines`.
  explicit ProgramCloth(const std::vector<std::string_view>& fragment, const std::string& defines = "");
  // u_view_projection, u_eye, then upload(), then the mesh.
  void draw(size_t handle, const glm::mat4& view_projection, const glm::vec3& eye, const SgLighting& sgs) override;

protected:
  // The mesh of a new object; returns its handle (objects are numbered 0, 1, ...).
  size_t add_mesh(const TriangleMesh& mesh);
  // The object's uniforms for this draw (the program is in use).
  virtual void upload(size_t handle, const GlProgram& program, const SgLighting& sgs) const = 0;

private:
  GlProgram program_;
  std::vector<GpuMesh> meshes_;
};

// The shader preamble, `defines` (#define lines), then each embedded part in order.
std::string program_source(const std::vector<std::string_view>& parts, const std::string& defines = "");
// `parts` followed by the method's main (a .frag).
std::vector<std::string_view> with_main(std::vector<std::string_view> parts, std::string_view main);

}  // namespace weft::gpu
