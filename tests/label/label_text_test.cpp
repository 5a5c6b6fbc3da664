// The label's text stack without GL: HarfBuzz advances grow with the text, FreeType's coverage
// is anti-aliased and lies inside the image, and a font that cannot be used is a clear error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "label/label_text.h"

namespace weft::label {
namespace {

TEST(LabelText, ALongerStringShapesWider) {
  const LabelFont font(kDefaultFontFile, 32);
  const double a = font.advance_px("Linen"), b = font.advance_px("Linen plain weave");
  EXPECT_GT(a, 40.0);
  EXPECT_GT(b, a + 100.0);
  EXPECT_EQ(font.advance_px(""), 0.0);
  // Kerning through HarfBuzz: "AV" is narrower than its glyphs' advances alone.
  EXPECT_LT(font.advance_px("AV"), font.advance_px("A") + font.advance_px("V"));
  // Twice the size, about twice the width.
  const LabelFont big(kDefaultFontFile, 64);
  EXPECT_NEAR(big.advance_px("Linen plain weave") / b, 2.0, 0.1);
}

TEST(LabelText, CoverageIsAntiAliasedAndInsideThePadding) {
  const LabelFont title(kDefaultFontFile, 32), detail(kDefaultFontFile, 20);
  const CoverageImage img = rasterise_lines({{"Linen plain", &title}, {"", &detail}, {"100 % linen", &detail}}, 6);
  ASSERT_GT(img.width, 0);
  EXPECT_GE(img.width, static_cast<int>(title.advance_px("Linen plain")) + 12);
  EXPECT_EQ(img.height, 6 + title.line_height_px() + detail.line_height_px() + 6);  // the empty line left out
  int full = 0, partial = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int c = img.at(x, y);
      full += c == 255;
      partial += c > 0 && c < 255;
      if (x < 5 || y < 5 || x >= img.width - 5 || y >= img.height - 5) { EXPECT_EQ(c, 0) << x << "," << y; }
    }
  EXPECT_GT(full, 100);
  EXPECT_GT(partial, 100);  // anti-aliased edges, not a 1-bit mask
  EXPECT_EQ(rasterise_lines({{"", &title}}, 6).width, 0);
}

TEST(LabelText, AFontThatCannotBeUsedIsAClearError) {
  const auto message = [](const std::filesystem::path& file, int size) -> std::string {
    try {
      LabelFont f(file, size);
    } catch (const LabelFontError& e) {
      return e.what();
    }
    return "";
  };
  const std::string missing = message("/nonexistent/Font.ttf", 32);
  EXPECT_NE(missing.find("/nonexistent/Font.ttf"), std::string::npos) << missing;
  EXPECT_NE(missing.find("no such file"), std::string::npos) << missing;
  const auto junk = std::filesystem::temp_directory_path() / ("weft_label_junk_" + std::to_string(::getpid()) + ".ttf");
  std::ofstream(junk) << "not a font";
  const std::string bad = message(junk, 32);
  std::filesystem::remove(junk);
  EXPECT_NE(bad.find("not a font"), std::string::npos) << bad;
  EXPECT_NE(message(kDefaultFontFile, 0).find("size"), std::string::npos);
}

}  // namespace
}  // namespace weft::label
