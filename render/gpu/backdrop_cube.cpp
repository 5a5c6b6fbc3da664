#include "gpu/backdrop_cube.h"

#include <glm/gtc/type_ptr.hpp>

#include "gl/gl_error.h"
#include "methods/program_cloth.h"
#include "methods/sg_lighting_uniforms.h"

namespace weft::gpu {

BackdropCube::BackdropCube(int face_size)
    : size_(face_size),
      fill_(fullscreen_triangle_vs(), program_source({"erf.glsl", "sg_lighting.glsl", "backdrop_cube_fill.frag"})),
      draw_(fullscreen_triangle_vs(), program_source({"backdrop_cube.frag"})) {
  if (face_size < 1 || face_size > 1024) throw GpuError("backdrop cube face of " + std::to_string(face_size) + " texels");
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &previous);
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture_);
  glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA16F, size_, size_);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_CUBE_MAP, GLuint(previous));
  glGenFramebuffers(1, &framebuffer_);
  check_gl("making the backdrop cube");
}

BackdropCube::~BackdropCube() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &texture_);
}

void BackdropCube::fill(const SgLighting& sgs) {
  GLint framebuffer = 0, viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer);
  glGetIntegerv(GL_VIEWPORT, viewport);
  const GLboolean depth = glIsEnabled(GL_DEPTH_TEST), blend = glIsEnabled(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  fill_.use();
  upload_sg_lighting(fill_, sgs);
  glUniform1f(fill_.uniform("u_face_size"), float(size_));
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, size_, size_);
  for (int face = 0; face < 6; ++face) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), texture_, 0);
    if (face == 0 && glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw GpuError("the backdrop cube's faces cannot be rendered to");
    glUniform1i(fill_.uniform("u_face"), face);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  if (depth) glEnable(GL_DEPTH_TEST);
  if (blend) glEnable(GL_BLEND);
  check_gl("filling the backdrop cube");
}

void BackdropCube::draw(const glm::mat4& inverse_view_projection, int width, int height) const {
  draw_.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture_);
  glUniform1i(draw_.uniform("u_backdrop"), 0);
  glUniformMatrix4fv(draw_.uniform("u_inverse_view_projection"), 1, GL_FALSE, glm::value_ptr(inverse_view_projection));
  glUniform2f(draw_.uniform("u_viewport"), float(width), float(height));
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace weft::gpu
