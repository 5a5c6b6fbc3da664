// The search's frame cost model (measure/frame_work.h) against hand-worked sums: cloth pixels
// scale with the frame's area to 640×480; per-pixel work takes the cloth's mean tangent samples
// over its vertices; per-vertex work adds each vertex's samples at kVertexStepCost plus the
// draw's cost per cloth pixel; and on the measured pillow (3764 cloth pixels at 160×120, 3+3
// samples, 10 SGs) the model orders per-vertex against per-pixel as frames measured apart from
// its calibration: at 160×120 (docs/bench/mesh_density/) level 1 (13 122 vertices) ran faster than
// per-pixel and level 2 (51 842) slower; at 640×480 level 2 stays faster (a quarter of the pixels'
// vertices' worth), and a cloth past the crossover does not.
#include <gtest/gtest.h>

#include "measure/frame_work.h"

using namespace weft;

TEST(FrameWork, ClothPixelsScaleWithTheFrameArea) {
  EXPECT_DOUBLE_EQ(kiosk_cloth_pixels(3764, 160, 120), 3764.0 * 16.0);
  EXPECT_DOUBLE_EQ(kiosk_cloth_pixels(1000, 640, 480), 1000.0);
  EXPECT_DOUBLE_EQ(kiosk_cloth_pixels(10, 64, 48), 1000.0);
}

TEST(FrameWork, PerPixelTakesTheVerticesMeanSamples) {
  // 300 vertices of a 3+3 fabric and 100 of a 15+1 one: 3·300·6 + ... over 400 vertices.
  const double vertex_samples = 300 * 6.0 + 100 * 16.0;
  EXPECT_DOUBLE_EQ(per_pixel_work(2000.0, 10, vertex_samples, 400.0), 2000.0 * 10 * (3400.0 / 400.0));
  EXPECT_DOUBLE_EQ(per_pixel_work(2000.0, 10, 0.0, 0.0), 0.0);  // no cloth
}

TEST(FrameWork, PerVertexPaysEachVertexAndEachPixelsDraw) {
  const double a = per_vertex_work(5000.0, 8, 1000 * 6.0);
  const double b = per_vertex_work(5000.0, 8, 4000 * 6.0);
  EXPECT_DOUBLE_EQ(b - a, kVertexStepCost * 8 * 3000 * 6.0);
  EXPECT_DOUBLE_EQ(per_vertex_work(5000.0, 8, 0.0), kVertexDrawPixelCost * 5000.0);
}

TEST(FrameWork, OrdersThePillowsLevelsAsMeasuredAt160x120) {
  const double pixels = kiosk_cloth_pixels(3764, 160, 120) / 16.0;  // a 160×120 frame's
  const double per_pixel = per_pixel_work(pixels, 10, 3362 * 6.0, 3362);
  EXPECT_LT(per_vertex_work(pixels, 10, 13122 * 6.0), per_pixel);
  EXPECT_GT(per_vertex_work(pixels, 10, 51842 * 6.0), per_pixel);
}

TEST(FrameWork, ThePillowsMeshShadesPerVertexADenseClothPerPixel) {
  const double pixels = kiosk_cloth_pixels(3764, 160, 120);
  const double per_pixel = per_pixel_work(pixels, 10, 3362 * 6.0, 3362);
  EXPECT_LT(per_vertex_work(pixels, 10, 3362 * 6.0), per_pixel);
  EXPECT_LT(per_vertex_work(pixels, 10, 51842 * 6.0), per_pixel);
  // Vertices at which the two cost the same: S·T·P = a·S·T·V + b·P.
  const double crossover = pixels * (10 * 6.0 - kVertexDrawPixelCost) / (kVertexStepCost * 10 * 6.0);
  EXPECT_LT(per_vertex_work(pixels, 10, 0.9 * crossover * 6.0), per_pixel);
  EXPECT_GT(per_vertex_work(pixels, 10, 1.1 * crossover * 6.0), per_pixel);
}
