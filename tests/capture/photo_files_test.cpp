// A capture's photo files: JPEGs are written whole or not at all, and a truncated or corrupt photo
// is refused with an error naming it (PhotoError; fit_capture turns it into a rejection) instead
// of libjpeg ending the process or padding the image with grey.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "capture/capture_fit.h"
#include "capture/capture_rejection.h"
#include "capture/photo_files.h"

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("weft_photo_files_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A smooth gradient with a sharp square: JPEG keeps it within a few codes.
weft::Photo test_photo(int w, int h) {
  weft::Photo p{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 3)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool square = x > w / 4 && x < w / 2 && y > h / 4 && y < h / 2;
      p.rgb[(static_cast<size_t>(y) * w + x) * 3 + 0] = static_cast<std::uint8_t>(square ? 230 : 255 * x / w);
      p.rgb[(static_cast<size_t>(y) * w + x) * 3 + 1] = static_cast<std::uint8_t>(square ? 20 : 255 * y / h);
      p.rgb[(static_cast<size_t>(y) * w + x) * 3 + 2] = 128;
    }
  return p;
}

std::vector<char> bytes_of(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& f, const std::vector<char>& b) { std::ofstream(f, std::ios::binary).write(b.data(), long(b.size())); }

template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const weft::PhotoError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PhotoFiles, JpegRoundTripKeepsThePicture) {
  const fs::path dir = scratch("round_trip");
  const weft::Photo photo = test_photo(320, 240);
  weft::write_jpeg(photo, dir / "a.jpg", 95);
  const weft::Photo back = weft::read_photo(dir / "a.jpg");
  ASSERT_EQ(back.width, 320);
  ASSERT_EQ(back.height, 240);
  double err = 0;
  for (size_t i = 0; i < photo.rgb.size(); ++i) err += std::abs(int(photo.rgb[i]) - int(back.rgb[i]));
  EXPECT_LT(err / photo.rgb.size(), 3.0);  // mean code error at quality 95
  // Only the photo in the folder: the temporary it went through is gone.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir.parent_path());
}

TEST(PhotoFiles, WriteReplacesWholeOrFailsNamingTheFile) {
  const fs::path dir = scratch("replace");
  weft::write_jpeg(test_photo(320, 240), dir / "a.jpg");
  weft::write_jpeg(test_photo(400, 300), dir / "a.jpg");
  EXPECT_EQ(weft::read_photo(dir / "a.jpg").width, 400);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  const std::string missing_dir = refusal([&] { weft::write_jpeg(test_photo(320, 240), dir / "no" / "a.jpg"); });
  EXPECT_NE(missing_dir.find((dir / "no" / "a.jpg").string()), std::string::npos) << missing_dir;
  // A photo whose pixels do not match its size is refused by the encoder (libjpeg never runs on it).
  weft::Photo bad = test_photo(320, 240);
  bad.rgb.resize(100);
  EXPECT_NE(refusal([&] { weft::write_jpeg(bad, dir / "b.jpg"); }), "");
  EXPECT_FALSE(fs::exists(dir / "b.jpg"));
  fs::remove_all(dir.parent_path());
}

TEST(PhotoFiles, TruncatedJpegIsRefusedNamingIt) {
  const fs::path dir = scratch("truncated");
  weft::write_jpeg(test_photo(640, 480), dir / "whole.jpg");
  const std::vector<char> whole = bytes_of(dir / "whole.jpg");
  // Cut inside the entropy-coded data: the header reads, the scan ends early.
  for (double keep : {0.5, 0.9}) {
    const fs::path cut = dir / "cut.jpg";
    write_bytes(cut, std::vector<char>(whole.begin(), whole.begin() + long(whole.size() * keep)));
    const std::string what = refusal([&] { weft::read_photo(cut); });
    EXPECT_NE(what.find("cut.jpg"), std::string::npos) << keep << ": " << what;
    EXPECT_NE(what.find("JPEG"), std::string::npos) << keep << ": " << what;
  }
  // Cut inside the header.
  write_bytes(dir / "head.jpg", std::vector<char>(whole.begin(), whole.begin() + 40));
  EXPECT_NE(refusal([&] { weft::read_photo(dir / "head.jpg"); }), "");
  // The markers after the header overwritten: not a decodable JPEG.
  std::vector<char> corrupt = whole;
  for (size_t i = 2; i < 400 && i < corrupt.size(); ++i) corrupt[i] = char(0xff);
  write_bytes(dir / "corrupt.jpg", corrupt);
  EXPECT_NE(refusal([&] { weft::read_photo(dir / "corrupt.jpg"); }), "");
  fs::remove_all(dir.parent_path());
}

TEST(PhotoFiles, CaptureWithATruncatedPhotoIsRejected) {
  const fs::path dir = scratch("capture");
  for (int i = 1; i <= 3; ++i) weft::write_jpeg(test_photo(640, 480), dir / ("photo_0" + std::to_string(i) + ".jpg"));
  const std::vector<char> whole = bytes_of(dir / "photo_01.jpg");
  write_bytes(dir / "photo_01.jpg", std::vector<char>(whole.begin(), whole.begin() + long(whole.size() / 2)));
  try {
    weft::fit_capture(dir, WEFT_SOURCE_ASSETS "/fabrics");
    ADD_FAILURE() << "a capture with a truncated photo was fitted";
  } catch (const weft::CaptureRejection& e) {
    EXPECT_NE(std::string(e.what()).find("photo_01.jpg"), std::string::npos) << e.what();
  }
  fs::remove_all(dir.parent_path());
}

TEST(PhotoFiles, BracketsAreFoundBesideTheirPhotoAndNotListedAsPhotos) {
  const fs::path dir = scratch("brackets");
  const weft::Photo p = test_photo(320, 240);
  for (const char* name : {"a.jpg", "a_ev-3.jpg", "a_ev-6.jpg", "a_ev-9.png", "b.jpg", "b_ev-3.jpg", "ab_ev-3.jpg"})
    weft::write_jpeg(p, dir / name);
  std::vector<std::string> photos;
  for (const fs::path& f : weft::list_photos(dir)) photos.push_back(f.filename().string());
  EXPECT_EQ(photos, (std::vector<std::string>{"a.jpg", "b.jpg"}));  // ab_ev-3 brackets a photo "ab" that is missing
  const auto a = weft::list_brackets(dir / "a.jpg");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].file.filename(), "a_ev-3.jpg");
  EXPECT_EQ(a[0].ev, -3);
  EXPECT_EQ(a[2].file.filename(), "a_ev-9.png");
  EXPECT_EQ(a[2].ev, -9);
  EXPECT_EQ(weft::list_brackets(dir / "b.jpg").size(), 1u);
  EXPECT_EQ(weft::bracket_path(dir / "a.jpg", -6), dir / "a_ev-6.jpg");
  fs::remove_all(dir.parent_path());
}
