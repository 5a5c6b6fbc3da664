#include "label/label_overlay.h"

#include <algorithm>

#include "gl/gl_error.h"
#include "shaders/embedded_shaders.h"

namespace weft::label {

std::optional<Corner> parse_corner(const std::string& name) {
  if (name == "bottom-left") return Corner::bottom_left;
  if (name == "bottom-right") return Corner::bottom_right;
  if (name == "top-left") return Corner::top_left;
  if (name == "top-right") return Corner::top_right;
  return std::nullopt;
}

const char* corner_names() { return "bottom-left, bottom-right, top-left or top-right"; }

Box place_box(Corner corner, int margin, int frame_width, int frame_height, int width, int height) {
  const int mx = std::clamp(std::min(margin, (frame_width - width) / 2), 0, margin);
  const int my = std::clamp(std::min(margin, (frame_height - height) / 2), 0, margin);
  const bool left = corner == Corner::bottom_left || corner == Corner::top_left;
  const bool bottom = corner == Corner::bottom_left || corner == Corner::bottom_right;
  return {left ? mx : frame_width - width - mx, bottom ? my : frame_height - height - my, width, height};
}

LabelOverlay::LabelOverlay(float plate_alpha)
    : program_(gpu::fullscreen_triangle_vs(),
               "#version 300 es\nprecision highp float;\nprecision highp int;\n" + std::string(shaders::source("label.frag"))),
      plate_alpha_(plate_alpha) {}

void LabelOverlay::set_image(const CoverageImage& image) {
  width_ = image.width;
  height_ = image.height;
  if (image.pixels.empty()) return;
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of any width
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, image.width, image.height, 0, GL_RED, GL_UNSIGNED_BYTE, image.pixels.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gpu::check_gl("label texture upload");
}

void LabelOverlay::draw(const Box& box, float opacity) const {
  if (opacity <= 0.0f || width_ == 0 || height_ == 0) return;
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  const GLboolean blend = glIsEnabled(GL_BLEND), depth = glIsEnabled(GL_DEPTH_TEST);
  // The fullscreen triangle over a viewport of the box: exactly the box's pixels are shaded.
  glViewport(box.x, box.y, box.width, box.height);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  program_.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glUniform1i(program_.uniform("u_coverage"), 0);
  glUniform2i(program_.uniform("u_origin"), box.x, box.y);
  glUniform1i(program_.uniform("u_height"), height_);
  glUniform1f(program_.uniform("u_plate"), plate_alpha_);
  glUniform1f(program_.uniform("u_opacity"), std::min(opacity, 1.0f));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  if (!blend) glDisable(GL_BLEND);
  if (depth) glEnable(GL_DEPTH_TEST);
}

}  // namespace weft::label
