#pragma once
// A screen mounted turned (portrait): the kiosk renders, tone-maps and labels its frame upright
// at the turned size, into the 8-bit picture here, which is then drawn onto the screen turned
// clockwise by the rotation. Screenshots read the upright picture, never the turned one.
#include <GLES3/gl3.h>

#include "gl/gl_program.h"

namespace weft::gpu {

class ScreenRotation {
public:
  explicit ScreenRotation(int rotation_deg);  // 90, 180 or 270 (clockwise); throws GpuError otherwise
  ScreenRotation(const ScreenRotation&) = delete;
  ScreenRotation& operator=(const ScreenRotation&) = delete;
  ~ScreenRotation();

  // Binds the upright picture, `width` × `height` (made again when the size changes), with the
  // viewport on all of it: draw the frame there as on an unturned screen.
  void bind_picture(int width, int height);
  // Draws the picture turned over the framebuffer bound now, which must be the picture's size
  // with its sides swapped for a quarter turn (the screen's mode).
  void draw_turned() const;
  int rotation() const { return rotation_; }

private:
  int rotation_;
  GlProgram program_;
  GLuint fbo_ = 0, texture_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace weft::gpu
