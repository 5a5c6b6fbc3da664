#pragma once
// 8-bit RGB to JPEG bytes (libjpeg-turbo), as a camera writes a photo; the caller puts the bytes
// in a file (atomically: files/atomic_file.h).
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace weft {

class JpegEncodeError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Colour resolution: halved both ways (4:2:0, most cameras' and libjpeg's default) or full (4:4:4,
// a camera's finest setting). Halved chroma tints a highlight a few pixels wide toward grey.
enum class JpegChroma { halved, full };

// `rgb`: width × height pixels, 3 bytes each, row 0 at the top; quality 1–100. Throws
// JpegEncodeError for a size that does not match, a side of 0 or beyond JPEG's 65500, or
// libjpeg's own errors.
std::vector<std::uint8_t> encode_jpeg(std::span<const std::uint8_t> rgb, int width, int height, int quality,
                                      JpegChroma chroma = JpegChroma::halved);

}  // namespace weft
