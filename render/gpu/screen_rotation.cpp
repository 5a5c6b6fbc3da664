#include "gpu/screen_rotation.h"

#include <string>

#include "gl/gl_error.h"
#include "shaders/embedded_shaders.h"

namespace weft::gpu {

ScreenRotation::ScreenRotation(int rotation_deg)
    : rotation_(rotation_deg),
      program_(fullscreen_triangle_vs(),
               "#version 300 es\nprecision highp float;\nprecision highp int;\n" + std::string(shaders::source("screen_rotation.frag"))) {
  if (rotation_deg != 90 && rotation_deg != 180 && rotation_deg != 270)
    throw GpuError("screen rotation must be 90, 180 or 270 degrees, got " + std::to_string(rotation_deg));
}

ScreenRotation::~ScreenRotation() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(1, &texture_);
}

void ScreenRotation::bind_picture(int width, int height) {
  if (width != width_ || height != height_) {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteTextures(1, &texture_);
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw GpuError("rotation picture " + std::to_string(width) + "x" + std::to_string(height) + " incomplete");
    check_gl("rotation picture");
    width_ = width;
    height_ = height;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

void ScreenRotation::draw_turned() const {
  program_.use();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glUniform1i(program_.uniform("u_picture"), 0);
  glUniform1i(program_.uniform("u_quarter_turns"), rotation_ / 90);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace weft::gpu
