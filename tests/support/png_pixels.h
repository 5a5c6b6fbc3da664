#pragma once
// A PNG read back as 8-bit RGB (libpng's simplified API), for tests that check what a screenshot shows.
#include <png.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace weft::test {

struct PngPixels {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // row 0 at the top
  const std::uint8_t* at(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

// Empty (width 0) when the file is not a readable PNG.
inline PngPixels read_png_rgb(const std::filesystem::path& file) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  PngPixels out;
  if (!png_image_begin_read_from_file(&image, file.c_str())) return out;
  image.format = PNG_FORMAT_RGB;
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr)) return {};
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  return out;
}

}  // namespace weft::test
