#include "image/texture_image.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include <png.h>

#include "image/jpeg_error.h"

namespace weft {

namespace {

void check_size(long width, long height, const std::string& what) {
  if (width < 1 || height < 1)
    throw TextureError(what + ": the image is empty (" + std::to_string(width) + "×" + std::to_string(height) + ")");
  if (width > kMaxTextureSide || height > kMaxTextureSide)
    throw TextureError(what + ": " + std::to_string(width) + "×" + std::to_string(height) + " texels exceed the " +
                       std::to_string(kMaxTextureSide) + "×" + std::to_string(kMaxTextureSide) + " a texture may have");
}

bool is_png(std::span<const std::uint8_t> b) {
  static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return b.size() >= 8 && std::memcmp(b.data(), signature, 8) == 0;
}
bool is_jpeg(std::span<const std::uint8_t> b) { return b.size() >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff; }

// libpng's simplified API: it converts every PNG kind to 8-bit RGBA and reports errors in its
// message instead of a longjmp.
TextureImage decode_png(std::span<const std::uint8_t> bytes, const std::string& what) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
    throw TextureError(what + ": not a readable PNG (" + image.message + ")");
  const long width = long(image.width), height = long(image.height);
  try {
    check_size(width, height, what);
  } catch (...) {
    png_image_free(&image);
    throw;
  }
  image.format = PNG_FORMAT_RGBA;
  TextureImage out;
  out.width = int(width);
  out.height = int(height);
  out.rgba.resize(size_t(width) * size_t(height) * 4);
  if (!png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr))
    throw TextureError(what + ": a corrupt PNG (" + image.message + ")");
  return out;
}

// libjpeg reports errors by its error_exit; a longjmp back here (image/jpeg_error.h) keeps them
// out of the caller, a truncated file among them. Nothing with a destructor lives between the
// setjmp and the calls that may jump.
TextureImage decode_jpeg(std::span<const std::uint8_t> bytes, const std::string& what) {
  jpeg_decompress_struct info;
  jpeg_detail::ErrorManager error;
  jpeg_detail::install(reinterpret_cast<jpeg_common_struct*>(&info), error);
  TextureImage out;
  if (setjmp(error.jump)) {
    jpeg_destroy_decompress(&info);
    throw TextureError(what + ": a corrupt JPEG (" + std::string(error.message) + ")");
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&info, TRUE);
  if (info.image_width < 1 || info.image_height < 1 || info.image_width > unsigned(kMaxTextureSide) ||
      info.image_height > unsigned(kMaxTextureSide)) {
    const long w = long(info.image_width), h = long(info.image_height);
    jpeg_destroy_decompress(&info);
    check_size(w, h, what);
  }
  info.out_color_space = JCS_EXT_RGBA;  // libjpeg-turbo's extension: grey and YCbCr alike
  jpeg_start_decompress(&info);
  out.width = int(info.output_width);
  out.height = int(info.output_height);
  out.rgba.resize(size_t(out.width) * size_t(out.height) * 4);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = out.rgba.data() + size_t(info.output_scanline) * size_t(out.width) * 4;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  return out;
}

}  // namespace

glm::dvec3 TextureImage::linear(int x, int y) const {
  const std::uint8_t* t = rgba.data() + (size_t(y) * size_t(width) + size_t(x)) * 4;
  return {srgb_to_linear(t[0] / 255.0), srgb_to_linear(t[1] / 255.0), srgb_to_linear(t[2] / 255.0)};
}

glm::dvec3 TextureImage::stored(int x, int y) const {
  const std::uint8_t* t = rgba.data() + (size_t(y) * size_t(width) + size_t(x)) * 4;
  return glm::dvec3(t[0], t[1], t[2]) / 255.0;
}

TextureImage decode_texture(std::span<const std::uint8_t> bytes, const std::string& what) {
  if (is_png(bytes)) return decode_png(bytes, what);
  if (is_jpeg(bytes)) return decode_jpeg(bytes, what);
  throw TextureError(what + ": neither a PNG nor a JPEG image (" + std::to_string(bytes.size()) + " bytes)");
}

std::vector<std::uint8_t> encode_png(const TextureImage& image) {
  png_image p;
  std::memset(&p, 0, sizeof p);
  p.version = PNG_IMAGE_VERSION;
  p.width = png_uint_32(image.width);
  p.height = png_uint_32(image.height);
  p.format = PNG_FORMAT_RGBA;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&p, nullptr, &size, 0, image.rgba.data(), 0, nullptr))
    throw TextureError(std::string("encoding a PNG: ") + p.message);
  std::vector<std::uint8_t> out(size);
  if (!png_image_write_to_memory(&p, out.data(), &size, 0, image.rgba.data(), 0, nullptr))
    throw TextureError(std::string("encoding a PNG: ") + p.message);
  out.resize(size);
  return out;
}

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

namespace {
// Bilinear between texel centres, repeating in both directions; `texel(x, y)` gives one texel.
template <class Texel>
glm::dvec3 bilinear(const TextureImage& image, glm::dvec2 uv, Texel&& texel) {
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return texel(0, 0);
  // Texel centres at (i + ½)/size, as GL_LINEAR with GL_REPEAT places them.
  const double x = uv.x * image.width - 0.5, y = uv.y * image.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double wx = x - fx, wy = y - fy;
  auto wrap = [](double i, int n) {
    const long m = long(std::fmod(i, double(n)));
    return int(m < 0 ? m + n : m);
  };
  const int x0 = wrap(fx, image.width), x1 = wrap(fx + 1, image.width);
  const int y0 = wrap(fy, image.height), y1 = wrap(fy + 1, image.height);
  return (1 - wy) * ((1 - wx) * texel(x0, y0) + wx * texel(x1, y0)) + wy * ((1 - wx) * texel(x0, y1) + wx * texel(x1, y1));
}
}  // namespace

glm::dvec3 sample_texture(const TextureImage& image, glm::dvec2 uv) {
  return bilinear(image, uv, [&](int x, int y) { return image.linear(x, y); });
}

glm::dvec3 sample_stored_texture(const TextureImage& image, glm::dvec2 uv) {
  return bilinear(image, uv, [&](int x, int y) { return image.stored(x, y); });
}

}  // namespace weft
