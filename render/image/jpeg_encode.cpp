#include "image/jpeg_encode.h"

#include <cstdlib>
#include <string>

#include "image/jpeg_error.h"

namespace weft {

std::vector<std::uint8_t> encode_jpeg(std::span<const std::uint8_t> rgb, int width, int height, int quality,
                                      JpegChroma chroma) {
  if (width < 1 || height < 1 || width > JPEG_MAX_DIMENSION || height > JPEG_MAX_DIMENSION)
    throw JpegEncodeError("encoding a JPEG: " + std::to_string(width) + "×" + std::to_string(height) + " pixels");
  if (rgb.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3)
    throw JpegEncodeError("encoding a JPEG: " + std::to_string(rgb.size()) + " bytes for " + std::to_string(width) + "×" +
                          std::to_string(height) + " RGB pixels");
  jpeg_compress_struct info;
  jpeg_detail::ErrorManager error;
  jpeg_detail::install(reinterpret_cast<jpeg_common_struct*>(&info), error);
  // jpeg_mem_dest's buffer: libjpeg allocates and grows it with malloc; freed here in every case.
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  if (setjmp(error.jump)) {
    jpeg_destroy_compress(&info);
    std::free(buffer);
    throw JpegEncodeError(std::string("encoding a JPEG: ") + error.message);
  }
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = static_cast<JDIMENSION>(width);
  info.image_height = static_cast<JDIMENSION>(height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, quality, TRUE);
  if (chroma == JpegChroma::full)
    for (int c = 0; c < 3; ++c) info.comp_info[c].h_samp_factor = info.comp_info[c].v_samp_factor = 1;
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(rgb.data() + static_cast<size_t>(info.next_scanline) * width * 3);
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::vector<std::uint8_t> out(buffer, buffer + size);
  std::free(buffer);
  return out;
}

}  // namespace weft
