#include "capture/photo_files.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <regex>
#include <span>
#include <system_error>

#include <nlohmann/json.hpp>

#include "files/atomic_file.h"
#include "image/texture_image.h"

namespace weft {

void write_jpeg(const Photo& photo, const std::filesystem::path& file, int quality, JpegChroma chroma) {
  try {
    const std::vector<std::uint8_t> bytes = encode_jpeg(photo.rgb, photo.width, photo.height, quality, chroma);
    write_file_atomically(file, std::as_bytes(std::span(bytes)));
  } catch (const JpegEncodeError& e) {
    throw PhotoError(file.string() + ": " + e.what());
  } catch (const std::system_error& e) {
    throw PhotoError(file.string() + ": cannot write (" + e.what() + ")");
  }
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

namespace {

bool is_photo(const std::filesystem::directory_entry& entry) {
  std::string ext = entry.path().extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return entry.is_regular_file() && (ext == ".jpg" || ext == ".jpeg" || ext == ".png");
}

// "<stem>_ev<N>": the stem of the photo it brackets and N.
std::optional<std::pair<std::string, double>> bracket_of(const std::filesystem::path& file) {
  static const std::regex pattern(R"((.+)_ev([+-]?[0-9]+(\.[0-9]+)?))");
  std::smatch m;
  const std::string stem = file.stem().string();
  if (!std::regex_match(stem, m, pattern)) return std::nullopt;
  return std::pair(m[1].str(), std::stod(m[2].str()));
}

}  // namespace

std::vector<std::filesystem::path> list_photos(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (is_photo(entry) && !bracket_of(entry.path()) && entry.path().stem() != kCloseupStem) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::optional<std::filesystem::path> closeup_photo(const std::filesystem::path& dir) {
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (is_photo(entry) && entry.path().stem() == kCloseupStem) return entry.path();
  return std::nullopt;
}

std::vector<BracketFile> list_brackets(const std::filesystem::path& photo) {
  std::vector<BracketFile> out;
  const std::filesystem::path dir = photo.has_parent_path() ? photo.parent_path() : std::filesystem::path(".");
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (is_photo(entry))
      if (const auto b = bracket_of(entry.path()); b && b->first == photo.stem().string())
        out.push_back({entry.path(), b->second});
  std::sort(out.begin(), out.end(), [](const BracketFile& a, const BracketFile& b) { return a.ev > b.ev; });
  return out;
}

std::filesystem::path bracket_path(const std::filesystem::path& photo, int ev) {
  return photo.parent_path() / (photo.stem().string() + "_ev" + (ev > 0 ? "+" : "") + std::to_string(ev) + photo.extension().string());
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
