#pragma once
// A float colour target (RGBA16F, or RGBA32F where the driver renders to it) with depth, for
// headless frames and for reading linear radiance back.
#include <GLES3/gl3.h>

#include <vector>

namespace weft::gpu {

class OffscreenTarget {
public:
  // Needs EXT_color_buffer_float (GLES 3.0 cannot render to float otherwise); throws GpuError.
  OffscreenTarget(int width, int height, bool full_float = true);
  OffscreenTarget(const OffscreenTarget&) = delete;
  ~OffscreenTarget();
  void bind() const;
  int width() const { return width_; }
  int height() const { return height_; }
  GLuint colour_texture() const { return colour_; }  // for tone mapping onto a display
  GLuint framebuffer() const { return fbo_; }
  // Linear RGBA, row 0 at the bottom (GL's convention), after glFinish.
  std::vector<float> read_rgba() const;

private:
  int width_, height_;
  GLuint fbo_ = 0, colour_ = 0, depth_ = 0;
};

}  // namespace weft::gpu
