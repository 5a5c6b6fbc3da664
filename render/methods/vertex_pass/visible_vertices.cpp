#include "methods/vertex_pass/visible_vertices.h"

#include <GLES3/gl32.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "gl/frame_profile.h"
#include "gl/gl_error.h"
#include "methods/vertex_pass/vertex_pass.h"
#include "shaders/embedded_shaders.h"

namespace weft::gpu {

namespace {
const char* kPreamble = "#version 320 es\nprecision highp float;\nprecision highp int;\n";

// Makes `program` current again, unless it was deleted while current: switching away released it,
// and using its name now would be an error.
void restore_program(GLint program) { glUseProgram(program != 0 && glIsProgram(GLuint(program)) ? GLuint(program) : 0); }

GLuint storage(const void* data, size_t bytes) {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, b);
  glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(bytes), data, GL_DYNAMIC_COPY);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  return b;
}
}  // namespace

bool VisibleVertices::supported() {
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  int major = 0, minor = 0;
  if (!version || std::sscanf(version, "OpenGL ES %d.%d", &major, &minor) != 2) return false;
  if (major * 10 + minor < 32) return false;
  GLint blocks = 0;
  glGetIntegerv(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS, &blocks);
  glGetError();  // an ES 3.0 context may refuse the query
  return blocks >= 2;
}

VisibleVertices::VisibleVertices()
    : program_(kPreamble + std::string(shaders::source("visible_vertices.vert")),
               kPreamble + std::string(shaders::source("visible_vertices.frag"))) {
  glGenFramebuffers(1, &fbo_);
  glGenRenderbuffers(1, &depth_);
}

VisibleVertices::~VisibleVertices() {
  for (const Mesh& m : meshes_) {
    glDeleteBuffers(1, &m.triangles);
    glDeleteBuffers(1, &m.marks);
  }
  glDeleteRenderbuffers(1, &depth_);
  glDeleteFramebuffers(1, &fbo_);
}

size_t VisibleVertices::add_mesh(const TriangleMesh& mesh, const GpuMesh& drawn, int texels) {
  std::vector<GLuint> indices;
  indices.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
  Mesh m;
  m.drawn = &drawn;
  m.vertices = int(mesh.positions.size());
  m.triangles = storage(indices.data(), std::max<size_t>(indices.size(), 1) * sizeof(GLuint));
  const std::vector<GLuint> zero(size_t(std::max(texels, m.vertices)), 0u);
  m.marks = storage(zero.data(), zero.size() * sizeof(GLuint));
  meshes_.push_back(m);
  view_projection_ = glm::mat4(0.0f);  // the new mesh holds no marks for the last view: mark again
  check_gl("visible vertices: a mesh's buffers");
  return meshes_.size() - 1;
}

unsigned VisibleVertices::mark(const glm::mat4& view_projection, int width, int height) {
  if (stamp_ != 0 && view_projection == view_projection_ && width == width_ && height == height_) return stamp_;
  if (width != width_ || height != height_) {
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);  // OffscreenTarget's depth
    width_ = width;
    height_ = height;
  }
  const StageScope stage(Stage::vertex_pass);  // the passes' own work: what they skip pays for it
  view_projection_ = view_projection;
  if (++stamp_ == 0) stamp_ = 1;  // 0 is never a view's

  GLint framebuffer = 0, viewport[4], program = 0, depth_func = GL_LESS;
  GLboolean depth_mask = GL_TRUE, colour_mask[4];
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer);
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  glGetIntegerv(GL_DEPTH_FUNC, &depth_func);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
  glGetBooleanv(GL_COLOR_WRITEMASK, colour_mask);
  const GLboolean depth_test = glIsEnabled(GL_DEPTH_TEST), blend = glIsEnabled(GL_BLEND),
                  offset = glIsEnabled(GL_POLYGON_OFFSET_FILL), cull = glIsEnabled(GL_CULL_FACE);

  // Where draw_depth already put every mesh's depth for this view into the bound framebuffer (the
  // kiosk's frame draws it before the cloth), the marks test against that depth: one draw of the
  // meshes instead of two, and no target of our own. Its depth lies four steps further away, so a
  // few more vertices pass (never fewer).
  const bool frame_depth = std::all_of(meshes_.begin(), meshes_.end(), [&](const Mesh& m) {
    return m.depth_view_projection == view_projection && m.depth_framebuffer == framebuffer && m.depth_viewport[0] == viewport[0] &&
           m.depth_viewport[1] == viewport[1] && m.depth_viewport[2] == width && m.depth_viewport[3] == height;
  });
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  program_.use();
  glUniformMatrix4fv(program_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
  glUniform1ui(program_.uniform("u_stamp"), stamp_);
  if (frame_depth) {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  } else {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    const GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glViewport(0, 0, width, height);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniform1i(program_.uniform("u_mark"), 0);
    for (const Mesh& m : meshes_) m.drawn->draw();
  }
  glUniform1i(program_.uniform("u_mark"), 1);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, -2.0f);  // toward the eye by two depth steps: a tie, or a rounding, passes
  for (const Mesh& m : meshes_) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, m.triangles);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, m.marks);
    m.drawn->draw();
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  glPolygonOffset(0.0f, 0.0f);

  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  restore_program(program);
  glDepthFunc(GLenum(depth_func));
  glDepthMask(depth_mask);
  if (!depth_test) glDisable(GL_DEPTH_TEST);
  if (blend) glEnable(GL_BLEND);
  if (!offset) glDisable(GL_POLYGON_OFFSET_FILL);
  if (cull) glEnable(GL_CULL_FACE);
  glColorMask(colour_mask[0], colour_mask[1], colour_mask[2], colour_mask[3]);
  check_gl("marking the visible vertices");
  return stamp_;
}

void VisibleVertices::mark_for(VertexPass& pass, size_t mesh, const glm::mat4& view_projection) {
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  const unsigned stamp = mark(view_projection, viewport[2], viewport[3]);
  pass.set_marks(marks(mesh), stamp);
}

void VisibleVertices::draw_depth(size_t mesh, const glm::mat4& view_projection) {
  Mesh& m = meshes_.at(mesh);
  m.depth_view_projection = view_projection;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &m.depth_framebuffer);
  glGetIntegerv(GL_VIEWPORT, m.depth_viewport);
  GLint program = 0;
  GLboolean colour_mask[4];
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  glGetBooleanv(GL_COLOR_WRITEMASK, colour_mask);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  program_.use();
  glUniformMatrix4fv(program_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
  glUniform1i(program_.uniform("u_mark"), 0);
  const GLboolean offset = glIsEnabled(GL_POLYGON_OFFSET_FILL);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, 4.0f);  // the draw's own fragment, rounded either way, still passes GL_LESS
  m.drawn->draw();
  glPolygonOffset(0.0f, 0.0f);
  if (!offset) glDisable(GL_POLYGON_OFFSET_FILL);
  glColorMask(colour_mask[0], colour_mask[1], colour_mask[2], colour_mask[3]);
  restore_program(program);
}

size_t VisibleVertices::visible(size_t mesh) const {
  const Mesh& m = meshes_.at(mesh);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.marks);
  const auto* p = static_cast<const GLuint*>(
      glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(m.vertices) * GLsizeiptr(sizeof(GLuint)), GL_MAP_READ_BIT));
  size_t n = 0;
  if (p)
    for (int i = 0; i < m.vertices; ++i) n += p[i] == stamp_ ? 1 : 0;
  glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  check_gl("reading the visible vertices' marks");
  return n;
}

}  // namespace weft::gpu
