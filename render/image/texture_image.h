#pragma once
// A cloth's colour texture (a glTF baseColorTexture, a scene's "texture"): 8-bit sRGB texels as
// decoded from PNG (libpng) or JPEG (libjpeg-turbo), and what the CPU side reads of it: the
// bilinear, repeating lookup in linear RGB that the GPU's sRGB sampler makes at its finest level
// (the reference and the parity tests sample through this).
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace weft {

// An image that cannot be used; what() names it (`what` as the caller gave it) and the reason.
class TextureError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The largest side a texture may have (a GLES 3 GPU guarantees 2048; kiosk GPUs take 8192).
inline constexpr int kMaxTextureSide = 8192;

struct TextureImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // sRGB-encoded RGBA, row 0 the image's top row (uv v = 0)
  glm::dvec3 linear(int x, int y) const;  // texel (x, y) in linear RGB (alpha ignored)
  glm::dvec3 stored(int x, int y) const;  // texel (x, y) as stored, in [0, 1]: a normal map's values
};

// A PNG or JPEG file's bytes (told apart by their signatures) as RGBA. Throws TextureError
// starting with `what` for another format, a corrupt or truncated file, a side of 0 or beyond
// kMaxTextureSide.
TextureImage decode_texture(std::span<const std::uint8_t> bytes, const std::string& what);
// The image as a PNG (RGBA, 8 bits): what a bundle stores. Throws TextureError on failure.
std::vector<std::uint8_t> encode_png(const TextureImage& image);

// IEC 61966-2-1's decoding of one sRGB value in [0, 1].
double srgb_to_linear(double encoded);

// The texture at `uv` (glTF's convention: (0, 0) the top-left corner of the image, v downwards),
// bilinear between texel centres in linear RGB, repeating in both directions.
glm::dvec3 sample_texture(const TextureImage& image, glm::dvec2 uv);
// The same lookup of the stored values, undecoded: what a linear (GL_RGBA8) sampler returns, as a
// normal map is read.
glm::dvec3 sample_stored_texture(const TextureImage& image, glm::dvec2 uv);

}  // namespace weft
