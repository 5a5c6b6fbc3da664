#pragma once
// Text for the kiosk's label: lines shaped with HarfBuzz (kerning, ligatures, any script the
// font covers) and rasterised with FreeType, anti-aliased, into one 8-bit coverage image. No GL.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace weft::label {

// The Debian font the kiosk uses unless told otherwise (fonts-dejavu-core).
inline constexpr const char* kDefaultFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// A font that cannot be used: what() names the file and why.
class LabelFontError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// One font file at one pixel size (the em's height in pixels).
class LabelFont {
public:
  // Throws LabelFontError when the file is missing, unreadable or not a font, or size_px is not
  // in [4, 512].
  LabelFont(const std::filesystem::path& file, int size_px);
  ~LabelFont();
  LabelFont(const LabelFont&) = delete;
  LabelFont& operator=(const LabelFont&) = delete;

  int size_px() const { return size_px_; }
  int ascender_px() const;    // above the baseline
  int descender_px() const;   // below the baseline, ≥ 0
  int line_height_px() const;

  struct Glyph {
    std::uint32_t index;  // in the font
    double x, y;          // pen position, pixels from the line's origin (y up)
  };
  // `utf8` shaped: its glyphs placed, and the pen's advance (the line's width in pixels).
  std::vector<Glyph> shape(const std::string& utf8, double* advance_px = nullptr) const;
  double advance_px(const std::string& utf8) const;

private:
  friend struct LabelRaster;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int size_px_;
};

// 8-bit coverage, row 0 at the top: 0 none, 255 full.
struct CoverageImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
  std::uint8_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

struct LabelLine {
  std::string text;
  const LabelFont* font;
};

// The lines stacked top to bottom, left-aligned, `padding_px` of empty border around them. Empty
// lines are left out; no lines: an empty image (width 0).
CoverageImage rasterise_lines(const std::vector<LabelLine>& lines, int padding_px);

}  // namespace weft::label
