#pragma once
// docs/design.md §6's accuracy measure over the cloth pixels, and an error map to look at.
#include <vector>

#include "image/image.h"
#include "reference/scene_render.h"

namespace weft::bench {

struct ClothError {
  double relative_rmse = 0.0;  // sqrt(mean over cloth pixels and channels of (x−r)²) / mean(r)
  size_t cloth_pixels = 0;
};

// Images of equal size; `kinds` from the reference. Throws std::invalid_argument on a size mismatch.
ClothError cloth_error(const Image& method, const Image& reference, const std::vector<PixelKind>& kinds);

// The same error over any set of pixels (e.g. a shadow, bench/shadow_mask.h), normalised by the
// reference's mean over that set; brightness_ratio = mean(x)/mean(r) there (> 1: too light).
struct MaskedError {
  double relative_rmse = 0.0, brightness_ratio = 0.0;
  size_t pixels = 0;
};
MaskedError masked_error(const Image& method, const Image& reference, const std::vector<bool>& mask);

// |x−r| / mean(r) per cloth pixel as a colour ramp (black 0 → red 0.5 → yellow ≥ 1), grey
// for other pixels: an sRGB-ready image (values in [0, 1]) for write_png_rgb8 (image/image.h).
Image error_map(const Image& method, const Image& reference, const std::vector<PixelKind>& kinds);

}  // namespace weft::bench
