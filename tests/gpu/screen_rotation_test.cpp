// The picture turned onto a portrait screen, pixel for pixel: each pixel of a picture with
// a different colour everywhere (drawn with scissored clears, no shader) must land where a
// clockwise turn puts it, written here as the image operations that make one: a quarter turn
// clockwise is the transpose with each row then mirrored; a half turn mirrors rows and columns.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "gl/display_target.h"
#include "gpu/egl_context.h"
#include "gpu/screen_rotation.h"

using namespace weft::gpu;

namespace {

constexpr int kW = 7, kH = 5;  // odd and unequal: a wrong axis or an off-by-one shows

struct Rgb {
  std::uint8_t r, g, b;
  bool operator==(const Rgb&) const = default;
};
using Picture = std::vector<std::vector<Rgb>>;  // [row from the top][column]

// The colour for picture pixel (x, y from the top), distinct for every pixel.
Rgb colour(int x, int y) { return {std::uint8_t(20 + 30 * x), std::uint8_t(20 + 40 * y), std::uint8_t(x * 16 + y)}; }

Picture from_rgb(const std::vector<std::uint8_t>& rgb, int w, int h) {
  Picture p(h, std::vector<Rgb>(w));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* q = &rgb[(std::size_t(y) * w + x) * 3];
      p[y][x] = {q[0], q[1], q[2]};
    }
  return p;
}

Picture transpose(const Picture& p) {
  Picture t(p[0].size(), std::vector<Rgb>(p.size()));
  for (std::size_t y = 0; y < p.size(); ++y)
    for (std::size_t x = 0; x < p[0].size(); ++x) t[x][y] = p[y][x];
  return t;
}
Picture mirror_rows(Picture p) {  // each row left-right
  for (auto& row : p) std::reverse(row.begin(), row.end());
  return p;
}
Picture mirror_columns(Picture p) {  // top-bottom
  std::reverse(p.begin(), p.end());
  return p;
}

// The upright picture drawn into the rotation's picture target, and that target read back.
Picture draw_upright(ScreenRotation& rotation) {
  rotation.bind_picture(kW, kH);
  glEnable(GL_SCISSOR_TEST);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const Rgb c = colour(x, y);
      glScissor(x, kH - 1 - y, 1, 1);  // GL's rows from the bottom
      glClearColor(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
    }
  glDisable(GL_SCISSOR_TEST);
  std::vector<std::uint8_t> rgba(kW * kH * 4), rgb;
  glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  for (int y = kH - 1; y >= 0; --y)
    for (int x = 0; x < kW; ++x) rgb.insert(rgb.end(), &rgba[(std::size_t(y) * kW + x) * 4], &rgba[(std::size_t(y) * kW + x) * 4 + 3]);
  return from_rgb(rgb, kW, kH);
}

Picture turned(ScreenRotation& rotation) {
  const bool quarter = rotation.rotation() != 180;
  const DisplayTarget screen(quarter ? kH : kW, quarter ? kW : kH);
  screen.bind();
  rotation.draw_turned();
  return from_rgb(screen.read_rgb(), screen.width(), screen.height());
}

}  // namespace

TEST(ScreenRotation, TurnsThePictureClockwisePixelForPixel) {
  EglContext ctx = EglContext::headless();
  for (const int deg : {90, 180, 270}) {
    SCOPED_TRACE(deg);
    ScreenRotation rotation(deg);
    const Picture upright = draw_upright(rotation);
    ASSERT_EQ(upright[0][0], colour(0, 0));  // the picture itself came back as drawn
    ASSERT_EQ(upright[kH - 1][kW - 1], colour(kW - 1, kH - 1));
    const Picture expected = deg == 90    ? mirror_rows(transpose(upright))
                             : deg == 180 ? mirror_columns(mirror_rows(upright))
                                          : mirror_columns(transpose(upright));
    EXPECT_EQ(turned(rotation), expected);
  }
  // Clockwise, as the flag says: after a quarter turn the picture's top-left pixel is at the
  // screen's top-right.
  ScreenRotation quarter(90);
  draw_upright(quarter);
  const Picture screen = turned(quarter);
  EXPECT_EQ(screen[0][kH - 1], colour(0, 0));
}

TEST(ScreenRotation, RefusesOtherAngles) {
  EglContext ctx = EglContext::headless();
  EXPECT_THROW(ScreenRotation(45), GpuError);
  EXPECT_THROW(ScreenRotation(0), GpuError);
}
