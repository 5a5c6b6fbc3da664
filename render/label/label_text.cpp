#include "label/label_text.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include <hb-ft.h>
#include <hb.h>

namespace weft::label {

// One FreeType library per font: fonts are few (two per label) and never shared across threads.
struct LabelFont::Impl {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  hb_font_t* hb = nullptr;
  ~Impl() {
    if (hb) hb_font_destroy(hb);
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }
};

LabelFont::LabelFont(const std::filesystem::path& file, int size_px) : impl_(std::make_unique<Impl>()), size_px_(size_px) {
  const std::string where = "font " + file.string();
  if (size_px < 4 || size_px > 512) throw LabelFontError(where + ": size " + std::to_string(size_px) + " px is not in [4, 512]");
  // FreeType's own errors are numbers; say first what an operator can act on.
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw LabelFontError(where + ": no such file");
  if (!std::ifstream(file, std::ios::binary)) throw LabelFontError(where + ": cannot be read");
  if (FT_Init_FreeType(&impl_->library)) throw LabelFontError(where + ": FreeType did not start");
  if (const FT_Error e = FT_New_Face(impl_->library, file.c_str(), 0, &impl_->face)) {
    impl_->face = nullptr;
    const char* why = FT_Error_String(e);
    throw LabelFontError(where + ": not a font FreeType reads (" + (why ? why : "error " + std::to_string(e)) + ")");
  }
  if (!FT_IS_SCALABLE(impl_->face)) throw LabelFontError(where + ": a bitmap font; the label needs an outline font (TrueType, OpenType)");
  if (FT_Set_Pixel_Sizes(impl_->face, 0, static_cast<FT_UInt>(size_px)))
    throw LabelFontError(where + ": cannot be set to " + std::to_string(size_px) + " px");
  impl_->hb = hb_ft_font_create_referenced(impl_->face);
  // Light hinting: vertical only, so HarfBuzz's advances stay the outlines' (even spacing).
  hb_ft_font_set_load_flags(impl_->hb, FT_LOAD_TARGET_LIGHT);
}

LabelFont::~LabelFont() = default;

int LabelFont::ascender_px() const { return static_cast<int>(std::ceil(impl_->face->size->metrics.ascender / 64.0)); }
int LabelFont::descender_px() const { return static_cast<int>(std::ceil(-impl_->face->size->metrics.descender / 64.0)); }
int LabelFont::line_height_px() const {
  return std::max(ascender_px() + descender_px(), static_cast<int>(std::ceil(impl_->face->size->metrics.height / 64.0)));
}

std::vector<LabelFont::Glyph> LabelFont::shape(const std::string& utf8, double* advance_px) const {
  hb_buffer_t* buf = hb_buffer_create();
  hb_buffer_add_utf8(buf, utf8.data(), static_cast<int>(utf8.size()), 0, static_cast<int>(utf8.size()));
  hb_buffer_guess_segment_properties(buf);
  hb_shape(impl_->hb, buf, nullptr, 0);
  unsigned n = 0;
  const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf, &n);
  const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &n);
  std::vector<Glyph> glyphs;
  glyphs.reserve(n);
  double x = 0, y = 0;  // 26.6 → pixels
  for (unsigned i = 0; i < n; ++i) {
    glyphs.push_back({info[i].codepoint, x + pos[i].x_offset / 64.0, y + pos[i].y_offset / 64.0});
    x += pos[i].x_advance / 64.0;
    y += pos[i].y_advance / 64.0;
  }
  hb_buffer_destroy(buf);
  if (advance_px) *advance_px = x;
  return glyphs;
}

double LabelFont::advance_px(const std::string& utf8) const {
  double a = 0;
  shape(utf8, &a);
  return a;
}

// The rasteriser reaches the FreeType face through this friend.
struct LabelRaster {
  static FT_Face face(const LabelFont& f) { return f.impl_->face; }
};

CoverageImage rasterise_lines(const std::vector<LabelLine>& lines, int padding_px) {
  struct Placed {
    const LabelLine* line;
    std::vector<LabelFont::Glyph> glyphs;
    double width;
    int baseline;  // rows from the image's top
  };
  std::vector<Placed> placed;
  int top = padding_px;
  double width = 0;
  for (const LabelLine& l : lines) {
    if (l.text.empty() || !l.font) continue;
    Placed p{&l, {}, 0, 0};
    p.glyphs = l.font->shape(l.text, &p.width);
    p.baseline = top + l.font->ascender_px();
    top += l.font->line_height_px();
    width = std::max(width, p.width);
    placed.push_back(std::move(p));
  }
  CoverageImage img;
  if (placed.empty()) return img;
  // A pixel more each side: anti-aliased edges and overhangs (italic, 'f') reach past the advance.
  img.width = static_cast<int>(std::ceil(width)) + 2 * padding_px + 2;
  img.height = top + padding_px;
  img.pixels.assign(static_cast<std::size_t>(img.width) * img.height, 0);
  for (const Placed& p : placed) {
    const FT_Face face = LabelRaster::face(*p.line->font);
    for (const LabelFont::Glyph& g : p.glyphs) {
      if (FT_Load_Glyph(face, g.index, FT_LOAD_TARGET_LIGHT | FT_LOAD_NO_BITMAP)) continue;  // a broken glyph: left out
      if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) continue;
      // The pen's fraction of a pixel moves the outline before it is rendered: even spacing.
      const double px = padding_px + 1 + g.x, py = p.baseline - g.y;
      const int ix = static_cast<int>(std::floor(px)), iy = static_cast<int>(std::floor(py));
      FT_Outline_Translate(&face->glyph->outline, static_cast<FT_Pos>(std::lround((px - ix) * 64)),
                           -static_cast<FT_Pos>(std::lround((py - iy) * 64)));
      if (FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL)) continue;
      const FT_Bitmap& bm = face->glyph->bitmap;
      const int x0 = ix + face->glyph->bitmap_left, y0 = iy - face->glyph->bitmap_top;
      for (unsigned r = 0; r < bm.rows; ++r) {
        const int y = y0 + static_cast<int>(r);
        if (y < 0 || y >= img.height) continue;
        for (unsigned c = 0; c < bm.width; ++c) {
          const int x = x0 + static_cast<int>(c);
          if (x < 0 || x >= img.width) continue;
          std::uint8_t& dst = img.pixels[static_cast<std::size_t>(y) * img.width + x];
          dst = std::max(dst, bm.buffer[static_cast<std::ptrdiff_t>(r) * bm.pitch + c]);
        }
      }
    }
  }
  return img;
}

}  // namespace weft::label
