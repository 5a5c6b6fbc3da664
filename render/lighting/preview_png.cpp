#include "lighting/preview_png.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "image/image.h"
#include "image/tone_map.h"

namespace weft {

namespace {
unsigned char to_srgb8(double linear) { return static_cast<unsigned char>(std::lround(srgb_encode(linear) * 255.0)); }
}  // namespace

void write_preview_png(const std::filesystem::path& path, std::span<const EnvMap> maps, int width) {
  if (maps.empty() || width < 8) throw EnvMapError(path, "nothing to preview");
  const int height = width / 2, gap = 4;
  const int total_width = static_cast<int>(maps.size()) * width + (static_cast<int>(maps.size()) - 1) * gap;
  const glm::dvec3 mean = mean_radiance(maps[0]);
  const double key = 0.2126 * mean.r + 0.7152 * mean.g + 0.0722 * mean.b;
  const double exposure = key > 0.0 ? 0.25 / key : 1.0;

  std::vector<unsigned char> rgb(static_cast<size_t>(total_width) * height * 3, 96);
  for (size_t m = 0; m < maps.size(); ++m) {
    const EnvMap small = resample(maps[m], width, height);
    const int x0 = static_cast<int>(m) * (width + gap);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3; ++c)
          rgb[(static_cast<size_t>(y) * total_width + x0 + x) * 3 + c] =
              to_srgb8(-std::expm1(-exposure * small.at(x, y)[c]));
  }

  try {
    write_png_rgb8(total_width, height, rgb, path);
  } catch (const std::runtime_error& e) {
    throw EnvMapError(path, e.what());
  }
}

}  // namespace weft
