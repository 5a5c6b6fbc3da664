#include "capture/photo_files.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <iterator>

#include <jpeglib.h>
#include <nlohmann/json.hpp>

#include "image/texture_image.h"

namespace weft {

void write_jpeg(const Photo& photo, const std::filesystem::path& file, int quality) {
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (!out) throw PhotoError(file.string() + ": cannot write");
  jpeg_compress_struct info;
  jpeg_error_mgr error;
  info.err = jpeg_std_error(&error);
  jpeg_create_compress(&info);
  jpeg_stdio_dest(&info, out);
  info.image_width = static_cast<JDIMENSION>(photo.width);
  info.image_height = static_cast<JDIMENSION>(photo.height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, quality, TRUE);
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(photo.rgb.data() + static_cast<size_t>(info.next_scanline) * photo.width * 3);
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  if (std::fclose(out) != 0) throw PhotoError(file.string() + ": cannot write");
}

Photo read_photo(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw PhotoError(file.string() + ": cannot read");
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  TextureImage image;
  try {
    image = decode_texture(bytes, file.string());
  } catch (const TextureError& e) {
    throw PhotoError(e.what());
  }
  Photo photo{image.width, image.height, std::vector<std::uint8_t>(static_cast<size_t>(image.width) * image.height * 3)};
  for (size_t p = 0; p < static_cast<size_t>(image.width) * image.height; ++p)
    for (int c = 0; c < 3; ++c) photo.rgb[p * 3 + c] = image.rgba[p * 4 + c];
  return photo;
}

std::vector<std::filesystem::path> list_photos(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::string ext = entry.path().extension().string();
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (entry.is_regular_file() && (ext == ".jpg" || ext == ".jpeg" || ext == ".png")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void write_capture_info(const CaptureInfo& info, const std::filesystem::path& file) {
  nlohmann::ordered_json j;
  j["width"] = info.width;
  j["height"] = info.height;
  if (info.focal_px) j["focal_length_px"] = *info.focal_px;
  std::ofstream(file) << j.dump(2) << "\n";
}

std::optional<CaptureInfo> read_capture_info(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    CaptureInfo info;
    info.width = j.value("width", 0);
    info.height = j.value("height", 0);
    if (j.contains("focal_length_px") && j["focal_length_px"].is_number()) info.focal_px = j["focal_length_px"].get<double>();
    return info;
  } catch (const nlohmann::json::exception& e) {
    throw PhotoError(file.string() + ": " + e.what());
  }
}

}  // namespace weft
