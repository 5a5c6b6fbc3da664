#include "capture/capture_card.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include <apriltag.h>
#include <tag36h11.h>

#include "image/image.h"
#include "image/tone_map.h"

namespace weft {

const CaptureCard& capture_card() {
  static const CaptureCard card;
  return card;
}

glm::dvec3 card_to_world(glm::dvec2 mm) { return {mm.x / 1000.0, (capture_card().height - mm.y) / 1000.0, 0.0}; }

glm::dvec2 world_to_card(const glm::dvec3& p) { return {p.x * 1000.0, capture_card().height - p.y * 1000.0}; }

std::array<std::array<bool, 10>, 10> tag_cells(int id) {
  // The family's own renderer draws the code: its bit layout is the detector's, by construction.
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  apriltag_family_t* family = tag36h11_create();
  if (id < 0 || static_cast<uint32_t>(id) >= family->ncodes) {
    tag36h11_destroy(family);
    throw std::invalid_argument("tag36h11 has no code " + std::to_string(id));
  }
  image_u8_t* image = apriltag_to_image(family, id);
  std::array<std::array<bool, 10>, 10> cells{};
  for (int y = 0; y < 10 && y < image->height; ++y)
    for (int x = 0; x < 10 && x < image->width; ++x) cells[y][x] = image->buf[y * image->stride + x] < 128;
  image_u8_destroy(image);
  tag36h11_destroy(family);
  return cells;
}

namespace {

const std::array<std::array<bool, 10>, 10>& cached_cells(int id) {
  static const std::array<std::array<std::array<bool, 10>, 10>, 6> all = [] {  // the ids the card prints
    std::array<std::array<std::array<bool, 10>, 10>, 6> a;
    for (int i = 0; i < 6; ++i) a[i] = tag_cells(i);
    return a;
  }();
  return all.at(id);
}

bool near_line(double d) { return std::abs(d) < 0.35; }  // printed outlines 0.7 mm wide

}  // namespace

double tag_reflectance(int id, double size, glm::dvec2 p) {
  const CaptureCard& card = capture_card();
  const double cell = size / 8.0;
  const int cx = static_cast<int>(std::floor(p.x / cell + 5.0)), cy = static_cast<int>(std::floor(p.y / cell + 5.0));
  if (cx < 0 || cx > 9 || cy < 0 || cy > 9) return -1.0;
  return cached_cells(id)[cy][cx] ? card.ink_reflectance : card.paper_reflectance;
}

double card_reflectance(glm::dvec2 mm, bool with_strip) {
  const CaptureCard& c = capture_card();
  const double bottom = c.height + (with_strip ? c.strip_height : 0.0);
  if (mm.x < 0 || mm.y < 0 || mm.x >= c.width || mm.y >= bottom) return 0.0;
  for (const CardTag& t : c.corner_tags) {
    const double r = tag_reflectance(t.id, t.size, mm - t.centre);
    if (r >= 0) return r;
  }
  for (const GreyPatch& g : c.patches)
    if (g.rect.contains(mm)) return g.reflectance;
  const CardRect& w = c.swatch_window;
  const bool in_x = mm.x > w.x0 - 0.35 && mm.x < w.x1 + 0.35, in_y = mm.y > w.y0 - 0.35 && mm.y < w.y1 + 0.35;
  if ((in_y && (near_line(mm.x - w.x0) || near_line(mm.x - w.x1))) || (in_x && (near_line(mm.y - w.y0) || near_line(mm.y - w.y1))))
    return c.ink_reflectance;
  if (near_line(glm::length(mm - c.ball_centre) - c.ball_radius)) return c.ink_reflectance;
  if (with_strip && mm.y >= c.height) {
    // The strip: a dashed cut line along its top, the marker.
    if (near_line(mm.y - c.height) && std::fmod(mm.x, 6.0) < 3.0) return c.ink_reflectance;
    for (const CardTag& t : {c.swatch_marker, c.closeup_tag}) {
      const double r = tag_reflectance(t.id, t.size, mm - t.centre);
      if (r >= 0) return r;
    }
  }
  return c.paper_reflectance;
}

void write_card_png(const std::filesystem::path& file, int dpi) {
  if (dpi < 50 || dpi > 1200) throw std::invalid_argument("--dpi must be in [50, 1200]");
  const CaptureCard& c = capture_card();
  const double px_per_mm = dpi / 25.4;
  const int w = static_cast<int>(std::lround(c.width * px_per_mm));
  const int h = static_cast<int>(std::lround((c.height + c.strip_height) * px_per_mm));
  std::vector<unsigned char> rgb(static_cast<size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Paper prints as 255, ink as 0, a patch as the sRGB code of its reflectance relative to the paper's.
      const double r = card_reflectance({(x + 0.5) / px_per_mm, (y + 0.5) / px_per_mm}, true);
      const double lin = r <= c.ink_reflectance ? 0.0 : std::clamp(r / c.paper_reflectance, 0.0, 1.0);
      const unsigned char v = static_cast<unsigned char>(std::lround(255.0 * srgb_encode(lin)));
      for (int k = 0; k < 3; ++k) rgb[(static_cast<size_t>(y) * w + x) * 3 + k] = v;
    }
  write_png_rgb8(w, h, rgb, file);
}

}  // namespace weft
