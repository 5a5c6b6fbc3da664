#include "gl/display_target.h"

#include <cstring>
#include <string>

#include "gl/gl_error.h"

namespace weft::gpu {

DisplayTarget::DisplayTarget(int width, int height) : width_(width), height_(height) {
  glGenRenderbuffers(1, &colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &colour_);
    throw GpuError("display target " + std::to_string(width) + "x" + std::to_string(height) + " incomplete: status " +
                   std::to_string(status));
  }
  check_gl("display target");
}

DisplayTarget::~DisplayTarget() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &colour_);
}

void DisplayTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

std::vector<std::uint8_t> DisplayTarget::read_rgb() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFinish();
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width_) * height_ * 4);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  check_gl("display target read");
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width_) * height_ * 3);
  for (int y = 0; y < height_; ++y) {
    const std::uint8_t* src = &rgba[static_cast<std::size_t>(height_ - 1 - y) * width_ * 4];
    std::uint8_t* dst = &rgb[static_cast<std::size_t>(y) * width_ * 3];
    for (int x = 0; x < width_; ++x) std::memcpy(dst + 3 * x, src + 4 * x, 3);
  }
  return rgb;
}

}  // namespace weft::gpu
