// The label drawn through the real GLES path (llvmpipe headless) over a grey frame and read back:
// white text at FreeType's coverage over the dark plate inside its box, the frame untouched
// outside it, half as strong at half opacity, and nothing at all once faded.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "gl/display_target.h"
#include "gpu/egl_context.h"
#include "label/label_overlay.h"
#include "label/label_text.h"

namespace weft::label {
namespace {

constexpr int kW = 320, kH = 240;
constexpr int kGrey = 128;
constexpr float kPlate = 0.55f;

std::vector<std::uint8_t> draw_over_grey(const LabelOverlay& overlay, const Box& box, float opacity) {
  gpu::DisplayTarget target(kW, kH);
  target.bind();
  glClearColor(kGrey / 255.0f, kGrey / 255.0f, kGrey / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  overlay.draw(box, opacity);
  return target.read_rgb();
}

// Premultiplied white over the plate, blended over grey: what a pixel of coverage c shows.
double expected(double c, double opacity) {
  const double a = (c + kPlate * (1 - c)) * opacity;
  return 255.0 * (c * opacity) + kGrey * (1 - a);
}

TEST(LabelOverlay, TextInItsBoxAndNothingOutside) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  const LabelFont font(kDefaultFontFile, 24);
  const CoverageImage img = rasterise_lines({{"Linen plain", &font}}, 4);
  LabelOverlay overlay(kPlate);
  overlay.set_image(img);
  const Box box = place_box(Corner::bottom_left, 10, kW, kH, img.width, img.height);
  EXPECT_EQ(box.x, 10);
  EXPECT_EQ(box.y, 10);
  for (float opacity : {1.0f, 0.5f}) {
    const std::vector<std::uint8_t> rgb = draw_over_grey(overlay, box, opacity);
    int white = 0, off = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const std::uint8_t* p = &rgb[(static_cast<size_t>(y) * kW + x) * 3];
        // Image rows run from the top; the box's lower-left is (box.x, box.y) from the bottom.
        const int ix = x - box.x, iy = y - (kH - box.y - box.height);
        const bool inside = ix >= 0 && iy >= 0 && ix < box.width && iy < box.height;
        const double want = inside ? expected(img.at(ix, iy) / 255.0, opacity) : kGrey;
        for (int c = 0; c < 3; ++c) {
          if (inside ? std::abs(p[c] - want) > 2.0 : p[c] != kGrey) ++off;
        }
        white += inside && p[0] >= 250;
      }
    EXPECT_EQ(off, 0) << "opacity " << opacity;
    if (opacity == 1.0f) EXPECT_GT(white, 150);  // the glyphs' full-coverage cores
    else EXPECT_EQ(white, 0);
  }
  // Fully faded: the frame is exactly as it was.
  const std::vector<std::uint8_t> faded = draw_over_grey(overlay, box, 0.0f);
  EXPECT_EQ(faded, std::vector<std::uint8_t>(static_cast<size_t>(kW) * kH * 3, kGrey));
}

TEST(LabelOverlay, EachCornerKeepsItsMargin) {
  EXPECT_EQ(place_box(Corner::top_right, 20, 640, 480, 100, 40).x, 640 - 100 - 20);
  EXPECT_EQ(place_box(Corner::top_right, 20, 640, 480, 100, 40).y, 480 - 40 - 20);
  EXPECT_EQ(place_box(Corner::top_left, 20, 640, 480, 100, 40).x, 20);
  EXPECT_EQ(place_box(Corner::bottom_right, 20, 640, 480, 100, 40).y, 20);
  // A frame barely larger than the box: the margin shrinks, the box stays on screen.
  const Box tight = place_box(Corner::bottom_right, 20, 110, 44, 100, 40);
  EXPECT_EQ(tight.x, 5);
  EXPECT_EQ(tight.y, 2);
  EXPECT_EQ(parse_corner("top-left"), Corner::top_left);
  EXPECT_FALSE(parse_corner("middle").has_value());
}

}  // namespace
}  // namespace weft::label
