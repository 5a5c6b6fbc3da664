#pragma once
// A capture's files: the photos (8-bit RGB, JPEG as a camera writes them, or PNG) and
// capture.json, what the camera records beside them (image size, focal length in pixels when its
// EXIF gives it).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

#include "image/jpeg_encode.h"

namespace weft {

struct Photo {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // row 0 at the top
  std::uint8_t at(int x, int y, int c) const { return rgb[(static_cast<size_t>(y) * width + x) * 3 + c]; }
};

struct CaptureInfo {
  int width = 0, height = 0;
  std::optional<double> focal_px;
};

// A photo that cannot be read; what() names the file.
class PhotoError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Replaces `file` atomically (a reader sees the old photo or the whole new one). Throws PhotoError.
void write_jpeg(const Photo& photo, const std::filesystem::path& file, int quality = 90,
                JpegChroma chroma = JpegChroma::halved);
// Throws PhotoError for an unreadable, corrupt or truncated file.
Photo read_photo(const std::filesystem::path& file);
// The photos of a capture folder (*.jpg, *.jpeg, *.png), sorted by name, their brackets and the
// close-up left out.
std::vector<std::filesystem::path> list_photos(const std::filesystem::path& dir);

// The close-up (closeup.jpg or .png): the swatch from straight above, close enough that each
// thread spans several pixels, shot right after the last photo without moving the swatch
// (capture/closeup_shot.h reads it). Nothing when the folder has none.
inline constexpr const char* kCloseupStem = "closeup";
std::optional<std::filesystem::path> closeup_photo(const std::filesystem::path& dir);

// A photo's darker exposures for the mirror ball's highlights (a camera's exposure bracketing,
// shot from the same pose right after it): <stem>_ev-3.jpg, <stem>_ev-6.jpg, … beside
// <stem>.jpg, the number being the exposure in stops relative to the photo.
struct BracketFile {
  std::filesystem::path file;
  double ev = 0;
};
// The brackets beside `photo`, brightest first.
std::vector<BracketFile> list_brackets(const std::filesystem::path& photo);
std::filesystem::path bracket_path(const std::filesystem::path& photo, int ev);

void write_capture_info(const CaptureInfo& info, const std::filesystem::path& file);
// capture.json, or nothing when the folder has none.
std::optional<CaptureInfo> read_capture_info(const std::filesystem::path& file);

}  // namespace weft
