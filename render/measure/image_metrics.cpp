#include "measure/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace weft::bench {

namespace {
double cloth_mean(const Image& r, const std::vector<PixelKind>& kinds) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < kinds.size(); ++i)
    if (kinds[i] == PixelKind::cloth) sum += r.pixels[i].r + r.pixels[i].g + r.pixels[i].b, ++n;
  return n ? sum / (3.0 * n) : 0.0;
}
void check(const Image& a, const Image& b, const std::vector<PixelKind>& kinds) {
  if (a.width != b.width || a.height != b.height || kinds.size() != b.pixels.size())
    throw std::invalid_argument("cloth_error: images of different sizes");
}
}  // namespace

ClothError cloth_error(const Image& method, const Image& reference, const std::vector<PixelKind>& kinds) {
  check(method, reference, kinds);
  std::vector<bool> cloth(kinds.size());
  for (size_t i = 0; i < kinds.size(); ++i) cloth[i] = kinds[i] == PixelKind::cloth;
  const MaskedError m = masked_error(method, reference, cloth);
  return {m.relative_rmse, m.pixels};
}

MaskedError masked_error(const Image& method, const Image& reference, const std::vector<bool>& mask) {
  if (method.width != reference.width || method.height != reference.height || mask.size() != reference.pixels.size())
    throw std::invalid_argument("masked_error: images or mask of different sizes");
  MaskedError e;
  double se = 0.0, sum_r = 0.0, sum_x = 0.0;
  for (size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) {
      const glm::dvec3 d = method.pixels[i] - reference.pixels[i];
      se += glm::dot(d, d);
      sum_r += reference.pixels[i].r + reference.pixels[i].g + reference.pixels[i].b;
      sum_x += method.pixels[i].r + method.pixels[i].g + method.pixels[i].b;
      ++e.pixels;
    }
  if (e.pixels == 0 || sum_r <= 0.0) return e;
  const double mean = sum_r / (3.0 * e.pixels);
  e.relative_rmse = std::sqrt(se / (3.0 * e.pixels)) / mean;
  e.brightness_ratio = sum_x / sum_r;
  return e;
}

Image error_map(const Image& method, const Image& reference, const std::vector<PixelKind>& kinds) {
  check(method, reference, kinds);
  const double mean = cloth_mean(reference, kinds);
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
