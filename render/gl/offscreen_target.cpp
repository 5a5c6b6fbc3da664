#include "gl/offscreen_target.h"

#include <cstring>
#include <string>

#include "gl/gl_error.h"

namespace weft::gpu {

namespace {
bool has_extension(const char* name) {
  GLint n = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint i = 0; i < n; ++i)
    if (std::strcmp(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i)), name) == 0) return true;
  return false;
}
}  // namespace

OffscreenTarget::OffscreenTarget(int width, int height, bool full_float) : width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw GpuError("offscreen target size " + std::to_string(width) + "x" + std::to_string(height) + " is out of range");
  if (!has_extension("GL_EXT_color_buffer_float"))
    throw GpuError("the GL driver cannot render to float targets (no GL_EXT_color_buffer_float)");
  // Leave the caller's texture binding as it was: a target must not steal a sampler's unit.
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  glGenTextures(1, &colour_);
  glBindTexture(GL_TEXTURE_2D, colour_);
  glTexStorage2D(GL_TEXTURE_2D, 1, full_float ? GL_RGBA32F : GL_RGBA16F, width, height);
  glBindTexture(GL_TEXTURE_2D, previous);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) throw GpuError("offscreen framebuffer incomplete: " + std::to_string(status));
}

OffscreenTarget::~OffscreenTarget() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteTextures(1, &colour_);
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

std::vector<float> OffscreenTarget::read_rgba() const {
  std::vector<float> pixels(size_t(width_) * height_ * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFinish();
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, pixels.data());
  return pixels;
}

}  // namespace weft::gpu
