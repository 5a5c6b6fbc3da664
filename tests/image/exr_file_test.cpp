// The EXR pair of image/image.h: what write_exr writes, read_exr reads back at float precision
// (values a half would round: 0.1, 1e−7, 1e5), with a data window that does not start at the
// origin (OpenEXR addresses slices by absolute coordinates), and a clear error naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include "image/image.h"

using namespace weft;

namespace {
std::filesystem::path temp(const std::string& name) { return std::filesystem::path(testing::TempDir()) / name; }
}  // namespace

TEST(ExrFile, WhatIsWrittenIsReadBackAtFloatPrecision) {
  Image image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) image.at(x, y) = {0.1 * (x + 1), 1e-7 * (y + 1), 1e5 + x + 10 * y};
  write_exr(image, temp("round_trip.exr"));
  const Image back = read_exr(temp("round_trip.exr"));
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(back.pixels[i][c], double(float(image.pixels[i][c]))) << i << "," << c;
}

TEST(ExrFile, ADataWindowOffTheOriginIsReadWhole) {
  // 4 × 2 pixels at (10, 20) … (13, 21), half-float channels: each pixel's value is its index.
  Imf::Header header(Imath::Box2i({0, 0}, {31, 31}), Imath::Box2i({10, 20}, {13, 21}));
  for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::HALF));
  std::vector<half> px(8 * 3);
  for (int i = 0; i < 8; ++i) px[3 * i] = half(float(i)), px[3 * i + 1] = half(2.0f * i), px[3 * i + 2] = half(0.5f);
  const size_t xs = 3 * sizeof(half), ys = 4 * xs;
  char* base = reinterpret_cast<char*>(px.data()) - 10 * std::ptrdiff_t(xs) - 20 * std::ptrdiff_t(ys);
  Imf::FrameBuffer fb;
  fb.insert("R", Imf::Slice(Imf::HALF, base, xs, ys));
  fb.insert("G", Imf::Slice(Imf::HALF, base + sizeof(half), xs, ys));
  fb.insert("B", Imf::Slice(Imf::HALF, base + 2 * sizeof(half), xs, ys));
  {
    Imf::OutputFile out(temp("window.exr").c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(2);
  }
  const Image back = read_exr(temp("window.exr"));
  ASSERT_EQ(back.width, 4);
  ASSERT_EQ(back.height, 2);
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(back.pixels[i].r, double(i));
    EXPECT_EQ(back.pixels[i].g, 2.0 * i);
    EXPECT_EQ(back.pixels[i].b, 0.5);
  }
}

TEST(ExrFile, AMissingOrForeignFileIsAnErrorNamingIt) {
  const std::filesystem::path missing = temp("no_such_frame.exr");
  try {
    read_exr(missing);
    FAIL() << "a missing file was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_frame.exr"), std::string::npos) << e.what();
  }
  Imf::Header header(2, 2);
  header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
  std::vector<float> y(4, 1.0f);
  Imf::FrameBuffer fb;
  fb.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(y.data()), sizeof(float), 2 * sizeof(float)));
  {
    Imf::OutputFile out(temp("luminance.exr").c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(2);
  }
  try {
    read_exr(temp("luminance.exr"));
    FAIL() << "a file without RGB was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no R channel"), std::string::npos) << e.what();
  }
}
