#pragma once
// The label on screen: a coverage image (label/label_text.h) uploaded as a GLES texture and drawn
// as a premultiplied, alpha-blended box over the bound framebuffer, after tone mapping (so the
// text is in display values and never enters the linear frame or its metering), at an opacity
// for fading. Needs the GL context current.
#include <optional>
#include <string>

#include "gl/gl_program.h"
#include "gl/gl_texture.h"
#include "label/label_text.h"

namespace weft::label {

enum class Corner { bottom_left, bottom_right, top_left, top_right };
// "bottom-left", "bottom-right", "top-left", "top-right"; nullopt for anything else.
std::optional<Corner> parse_corner(const std::string& name);
const char* corner_names();  // for messages: "bottom-left, bottom-right, top-left or top-right"

// A box in framebuffer pixels, GL's way up: (x, y) is its lower-left pixel.
struct Box {
  int x = 0, y = 0, width = 0, height = 0;
};
// A width × height box in `corner` of a frame_width × frame_height frame, `margin` pixels in from
// both edges (less when the frame is too small for it; a box larger than the frame overhangs its
// far side, which GL clips).
Box place_box(Corner corner, int margin, int frame_width, int frame_height, int width, int height);

class LabelOverlay {
public:
  // The plate behind the text: black at this alpha (0: none), so white text reads on any fabric.
  explicit LabelOverlay(float plate_alpha = 0.55f);
  // Replaces the texture; an empty image (no text) draws nothing.
  void set_image(const CoverageImage& image);
  int width() const { return width_; }
  int height() const { return height_; }
  // Blends the label over the bound framebuffer at `box` (width × height of the image); the
  // viewport and blending are restored. Draws nothing at opacity ≤ 0 or without an image.
  void draw(const Box& box, float opacity) const;

private:
  gpu::GlProgram program_;
  gpu::GlTexture texture_;
  int width_ = 0, height_ = 0;
  float plate_alpha_;
};

}  // namespace weft::label
