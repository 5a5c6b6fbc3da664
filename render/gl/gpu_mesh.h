#pragma once
// A scene mesh on the GPU: one interleaved vertex buffer (position, normal, warp, a per-vertex
// RGB slot the CPU refills when the lighting changes) and an index buffer.
#include <GLES3/gl3.h>

#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"

namespace weft::gpu {

// Attribute locations shared by every Weft vertex shader.
enum VertexAttribute : GLuint { kPosition = 0, kNormal = 1, kWarp = 2, kVertexColour = 3 };

class GpuMesh {
public:
  explicit GpuMesh(const TriangleMesh& mesh);
  GpuMesh(GpuMesh&& o) noexcept;
  GpuMesh(const GpuMesh&) = delete;
  ~GpuMesh();
  // Replaces the per-vertex colour slot (e.g. SG irradiance of a Lambertian surface).
  void set_vertex_colours(const std::vector<glm::vec3>& colours);
  // A further static vec3 attribute at `location` (one value per vertex); again at the same
  // location, its values replaced in place.
  void add_attribute(GLuint location, const std::vector<glm::vec3>& values);
  void draw() const;
  size_t vertex_count() const { return vertices_; }

private:
  GLuint vao_ = 0, vbo_ = 0, ibo_ = 0, colour_vbo_ = 0;
  std::vector<GLuint> extra_vbos_;
  std::vector<GLuint> extra_locations_;  // each extra VBO's attribute location
  GLsizei indices_ = 0;
  size_t vertices_ = 0;
};

}  // namespace weft::gpu
