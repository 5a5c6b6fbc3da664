#pragma once
// A linked GLSL ES program. Compile and link errors come back as GpuError with the log and
// the offending source line, so a broken shader says where it broke.
#include <GLES3/gl3.h>

#include <string>

namespace weft::gpu {

// Vertex shader of a fullscreen pass: one triangle covering the viewport, drawn with
// glDrawArrays(GL_TRIANGLES, 0, 3) and no attributes.
const char* fullscreen_triangle_vs();

class GlProgram {
public:
  GlProgram(const std::string& vertex_source, const std::string& fragment_source);
  GlProgram(GlProgram&& o) noexcept : id_(o.id_) { o.id_ = 0; }
  GlProgram(const GlProgram&) = delete;
  ~GlProgram();
  GLuint id() const { return id_; }
  void use() const { glUseProgram(id_); }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

private:
  GLuint id_ = 0;
};

}  // namespace weft::gpu
