#include "measure/frame_work.h"

namespace weft {

double kiosk_cloth_pixels(double cloth_pixels, int width, int height) {
  return cloth_pixels * (double(kKioskWidth) * kKioskHeight) / (double(width) * height);
}

double per_pixel_work(double kiosk_pixels, int sgs, double vertex_samples, double vertices) {
  if (vertices <= 0.0) return 0.0;
  return kiosk_pixels * double(sgs) * vertex_samples / vertices;
}

double per_vertex_work(double kiosk_pixels, int sgs, double vertex_samples) {
  return kVertexStepCost * double(sgs) * vertex_samples + kVertexDrawPixelCost * kiosk_pixels;
}

}  // namespace weft
