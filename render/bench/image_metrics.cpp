#include "bench/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace weft::bench {

namespace {
double cloth_mean(const Image& r, const std::vector<PixelKind>& kinds, size_t* count) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < kinds.size(); ++i)
    if (kinds[i] == PixelKind::cloth) sum += r.pixels[i].r + r.pixels[i].g + r.pixels[i].b, ++n;
  if (count) *count = n;
  return n ? sum / (3.0 * n) : 0.0;
}
void check(const Image& a, const Image& b, const std::vector<PixelKind>& kinds) {
  if (a.width != b.width || a.height != b.height || kinds.size() != b.pixels.size())
    throw std::invalid_argument("cloth_error: images of different sizes");
}
}  // namespace

ClothError cloth_error(const Image& method, const Image& reference, const std::vector<PixelKind>& kinds) {
  check(method, reference, kinds);
  ClothError e;
  const double mean = cloth_mean(reference, kinds, &e.cloth_pixels);
  double se = 0.0;
  for (size_t i = 0; i < kinds.size(); ++i)
    if (kinds[i] == PixelKind::cloth) {
      const glm::dvec3 d = method.pixels[i] - reference.pixels[i];
      se += glm::dot(d, d);
    }
  if (e.cloth_pixels == 0 || mean <= 0.0) return e;
  e.relative_rmse = std::sqrt(se / (3.0 * e.cloth_pixels)) / mean;
  return e;
}

Image error_map(const Image& method, const Image& reference, const std::vector<PixelKind>& kinds) {
  check(method, reference, kinds);
  const double mean = cloth_mean(reference, kinds, nullptr);
  Image m(reference.width, reference.height);
  for (size_t i = 0; i < kinds.size(); ++i) {
    if (kinds[i] != PixelKind::cloth || mean <= 0.0) {
      m.pixels[i] = glm::dvec3(0.25);
      continue;
    }
    const double e = glm::length(method.pixels[i] - reference.pixels[i]) / std::sqrt(3.0) / mean;
    const double t = std::clamp(e, 0.0, 1.0);
    m.pixels[i] = t < 0.5 ? glm::dvec3(2 * t, 0, 0) : glm::dvec3(1, 2 * (t - 0.5), 0);
  }
  return m;
}

}  // namespace weft::bench
