#pragma once
// An 8-bit RGBA target standing in for the display's framebuffer where there is none (headless
// screenshots, tests): what the tone mapper and the label draw on KMS, drawn here instead and
// read back as the bytes a screen would show.
#include <GLES3/gl3.h>

#include <cstdint>
#include <vector>

namespace weft::gpu {

class DisplayTarget {
public:
  DisplayTarget(int width, int height);  // throws GpuError when the driver cannot render to it
  DisplayTarget(const DisplayTarget&) = delete;
  DisplayTarget& operator=(const DisplayTarget&) = delete;
  ~DisplayTarget();
  void bind() const;  // and sets the viewport to the whole target
  int width() const { return width_; }
  int height() const { return height_; }
  // RGB bytes, row 0 at the top (as images are stored), after glFinish.
  std::vector<std::uint8_t> read_rgb() const;

private:
  int width_, height_;
  GLuint fbo_ = 0, colour_ = 0;
};

}  // namespace weft::gpu
