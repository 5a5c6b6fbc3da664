#pragma once
// A linear-radiance RGB image and its two file forms: OpenEXR (float, lossless: for
// measuring) and a tone-mapped 8-bit sRGB PNG (for people to look at).
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

namespace weft {

struct Image {
  int width = 0, height = 0;
  std::vector<glm::dvec3> pixels;  // row-major, row 0 at the top
  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h, glm::dvec3(0.0)) {}
  glm::dvec3& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
  const glm::dvec3& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

// RGB float EXR (ZIP compression). Throws std::runtime_error naming the file.
void write_exr(const Image& image, const std::filesystem::path& file);
// An EXR's R, G and B channels at float precision (any pixel type; the data window's size).
// Throws std::runtime_error naming the file where it cannot be read or lacks a channel.
Image read_exr(const std::filesystem::path& file);
// 8-bit sRGB PNG through the display operator of image/tone_map.h (exposure, filmic curve,
// sRGB): display_value(radiance, exposure) per channel.
void write_png(const Image& image, const std::filesystem::path& file, double exposure = 1.0);
// 8-bit RGB bytes already in display values (a screen's framebuffer read back), row 0 at the top.
void write_png_rgb8(int width, int height, const std::vector<unsigned char>& rgb, const std::filesystem::path& file);
// The metered exposure (tone_map.h) of the pixels where `include` is true (all when empty):
// their log-average luminance maps to kMeteringKey, times 2^bias_ev.
double auto_exposure(const Image& image, const std::vector<bool>& include = {}, double bias_ev = 0.0);

}  // namespace weft
