#include "gl/gpu_mesh.h"

#include "gl/gl_error.h"

namespace weft::gpu {

GpuMesh::GpuMesh(const TriangleMesh& mesh) : vertices_(mesh.positions.size()) {
  struct Vertex {
    glm::vec3 position, normal, warp;
  };
  std::vector<Vertex> v(vertices_);
  for (size_t i = 0; i < vertices_; ++i) {
    v[i].position = glm::vec3(mesh.positions[i]);
    v[i].normal = i < mesh.normals.size() ? glm::vec3(mesh.normals[i]) : glm::vec3(0, 0, 1);
    v[i].warp = i < mesh.warps.size() ? glm::vec3(mesh.warps[i]) : glm::vec3(1, 0, 0);
  }
  std::vector<GLuint> idx;
  idx.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) idx.insert(idx.end(), t.begin(), t.end());
  indices_ = static_cast<GLsizei>(idx.size());

  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, v.size() * sizeof(Vertex), v.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(kPosition);
  glVertexAttribPointer(kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), (void*)offsetof(Vertex, position));
  glEnableVertexAttribArray(kNormal);
  glVertexAttribPointer(kNormal, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), (void*)offsetof(Vertex, normal));
  glEnableVertexAttribArray(kWarp);
  glVertexAttribPointer(kWarp, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), (void*)offsetof(Vertex, warp));
  glGenBuffers(1, &colour_vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, colour_vbo_);
  std::vector<glm::vec3> zero(vertices_, glm::vec3(0));
  glBufferData(GL_ARRAY_BUFFER, zero.size() * sizeof(glm::vec3), zero.data(), GL_DYNAMIC_DRAW);
  glEnableVertexAttribArray(kVertexColour);
  glVertexAttribPointer(kVertexColour, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glGenBuffers(1, &ibo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, idx.size() * sizeof(GLuint), idx.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

GpuMesh::GpuMesh(GpuMesh&& o) noexcept
    : vao_(o.vao_), vbo_(o.vbo_), ibo_(o.ibo_), colour_vbo_(o.colour_vbo_), extra_vbos_(std::move(o.extra_vbos_)), extra_locations_(std::move(o.extra_locations_)),
      indices_(o.indices_), vertices_(o.vertices_) {
  o.vao_ = o.vbo_ = o.ibo_ = o.colour_vbo_ = 0;
  o.extra_vbos_.clear();
  o.extra_locations_.clear();
}

GpuMesh::~GpuMesh() {
  if (!vao_) return;
  glDeleteBuffers(1, &vbo_);
  glDeleteBuffers(1, &colour_vbo_);
  glDeleteBuffers(1, &ibo_);
  if (!extra_vbos_.empty()) glDeleteBuffers(GLsizei(extra_vbos_.size()), extra_vbos_.data());
  glDeleteVertexArrays(1, &vao_);
}

void GpuMesh::set_vertex_colours(const std::vector<glm::vec3>& colours) {
  if (colours.size() != vertices_) throw GpuError("vertex colour count does not match the mesh");
  glBindBuffer(GL_ARRAY_BUFFER, colour_vbo_);
  glBufferSubData(GL_ARRAY_BUFFER, 0, colours.size() * sizeof(glm::vec3), colours.data());
}

void GpuMesh::add_attribute(GLuint location, const std::vector<glm::vec3>& values) {
  if (values.size() != vertices_) throw GpuError("attribute value count does not match the mesh");
  for (size_t i = 0; i < extra_locations_.size(); ++i)
    if (extra_locations_[i] == location) {
      glBindBuffer(GL_ARRAY_BUFFER, extra_vbos_[i]);
      glBufferSubData(GL_ARRAY_BUFFER, 0, values.size() * sizeof(glm::vec3), values.data());
      return;
    }
  GLuint vbo = 0;
  glGenBuffers(1, &vbo);
  extra_vbos_.push_back(vbo);
  extra_locations_.push_back(location);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, values.size() * sizeof(glm::vec3), values.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindVertexArray(0);
}

void GpuMesh::draw() const {
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, indices_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

}  // namespace weft::gpu
