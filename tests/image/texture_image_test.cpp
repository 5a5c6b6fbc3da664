// Cloth textures: PNG and JPEG files decode (a real JPEG from Debian's assimp-testmodels, PNGs
// round-tripped through the bundle's encoder), bad images are refused naming them, and the CPU
// lookup is IEC 61966-2-1's sRGB curve with bilinear, repeating filtering between texel centres.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "image/texture_image.h"

using namespace weft;

namespace {

TextureImage checker(int w, int h) {
  TextureImage t;
  t.width = w, t.height = h;
  t.rgba.resize(size_t(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = &t.rgba[(size_t(y) * w + x) * 4];
      p[0] = uint8_t(x * 255 / std::max(w - 1, 1)), p[1] = uint8_t(y * 255 / std::max(h - 1, 1));
      p[2] = ((x + y) % 2) ? 200 : 10, p[3] = 255;
    }
  return t;
}

std::vector<uint8_t> file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expect_refused(const std::vector<uint8_t>& bytes, const std::string& reason) {
  try {
    decode_texture(bytes, "materials[0] ('plaid') image 'cloth.png'");
    FAIL() << "accepted: " << reason;
  } catch (const TextureError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("materials[0] ('plaid') image 'cloth.png'"), std::string::npos) << what;
    EXPECT_NE(what.find(reason), std::string::npos) << what;
  }
}

}  // namespace

TEST(TextureImage, PngRoundTripsEveryTexel) {
  const TextureImage a = checker(13, 7);  // not a power of two
  const TextureImage b = decode_texture(encode_png(a), "round trip");
  EXPECT_EQ(b.width, 13);
  EXPECT_EQ(b.height, 7);
  EXPECT_EQ(b.rgba, a.rgba);
}

TEST(TextureImage, DecodesARealJpeg) {
  const std::filesystem::path f = "/usr/share/assimp/models/glTF2/ClearCoat-glTF/PlasticWrap_normals.jpg";
  if (!std::filesystem::exists(f)) GTEST_SKIP() << f << " absent (apt-get install assimp-testmodels)";
  const TextureImage t = decode_texture(file_bytes(f), f.string());
  EXPECT_EQ(t.width, 1024);  // its JFIF header's size (file(1) says 1024x1024)
  EXPECT_EQ(t.height, 1024);
  // A normal map: blue (z) is the largest channel nearly everywhere, alpha opaque.
  size_t blue_most = 0;
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    blue_most += t.rgba[i + 2] >= t.rgba[i] && t.rgba[i + 2] >= t.rgba[i + 1];
    ASSERT_EQ(t.rgba[i + 3], 255);
  }
  EXPECT_GT(double(blue_most) / (t.rgba.size() / 4), 0.9);
}

TEST(TextureImage, RefusesBadImagesNamingThem) {
  const std::vector<uint8_t> png = encode_png(checker(16, 16));
  expect_refused({}, "neither a PNG nor a JPEG");
  expect_refused({'G', 'I', 'F', '8', '9', 'a', 0, 0}, "neither a PNG nor a JPEG");
  std::vector<uint8_t> truncated(png.begin(), png.begin() + long(png.size() / 2));
  expect_refused(truncated, "PNG");
  std::vector<uint8_t> corrupt = png;
  for (size_t i = 40; i < corrupt.size() - 12; i += 7) corrupt[i] ^= 0x5a;  // inside IDAT
  expect_refused(corrupt, "PNG");
  expect_refused(encode_png(checker(kMaxTextureSide + 1, 1)), "exceed");
  const std::vector<uint8_t> jpeg_start = {0xff, 0xd8, 0xff, 0xe0, 0x00, 0x10, 'J', 'F', 'I', 'F', 0};
  expect_refused(jpeg_start, "JPEG");
}

TEST(TextureImage, SrgbCurveIsTheStandardOne) {
  EXPECT_DOUBLE_EQ(srgb_to_linear(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgb_to_linear(1.0), 1.0);
  EXPECT_NEAR(srgb_to_linear(0.04045), 0.04045 / 12.92, 1e-12);  // the linear segment's end
  EXPECT_NEAR(srgb_to_linear(0.5), 0.214041140, 1e-8);          // ((0.5 + 0.055)/1.055)^2.4
}

TEST(TextureImage, SamplesBilinearBetweenTexelCentresAndRepeats) {
  TextureImage t;
  t.width = 2, t.height = 2;
  // Texels (x, y): red channel 0, 255 in row 0; 255, 0 in row 1.
  t.rgba = {0, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 0, 0, 0, 255};
  // At a texel centre, the texel.
  EXPECT_NEAR(sample_texture(t, {0.25, 0.25}).r, 0.0, 1e-12);
  EXPECT_NEAR(sample_texture(t, {0.75, 0.25}).r, 1.0, 1e-12);
  // Halfway between the centres of row 0: the mean of the linear values.
  EXPECT_NEAR(sample_texture(t, {0.5, 0.25}).r, 0.5, 1e-12);
  // A quarter of the way from (0,0)'s centre towards (1,0)'s, and a quarter down towards row 1.
  EXPECT_NEAR(sample_texture(t, {0.375, 0.375}).r, 0.75 * (0.25 * 1.0) + 0.25 * (0.75 * 1.0), 1e-12);
  // Repeats: u + 1 and v − 3 read the same.
  EXPECT_NEAR(sample_texture(t, {1.375, -2.625}).r, sample_texture(t, {0.375, 0.375}).r, 1e-12);
  // The image's edge blends with the opposite edge (GL_REPEAT).
  EXPECT_NEAR(sample_texture(t, {0.0, 0.25}).r, 0.5, 1e-12);
}
