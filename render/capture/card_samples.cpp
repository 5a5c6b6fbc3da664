#include "capture/card_samples.h"

#include <algorithm>
#include <cmath>

#include "capture/capture_card.h"

namespace weft {

namespace {

constexpr double kPatchMarginMm = 2.5;  // clear of the patch's printed edge and the JPEG's blur
constexpr double kPaperCellMm = 8.0;
constexpr double kPaperMarginMm = 1.5;  // a cell's pixels stay this far from any print
constexpr double kSwatchCornerMm = 49.5;  // half the diagonal of a 70 mm swatch, any turn
constexpr double kClearMm = 3.0;
constexpr int kMinPixels = 24;

std::array<std::uint8_t, 3> code_at(const Photo& p, int x, int y) { return {p.at(x, y, 0), p.at(x, y, 1), p.at(x, y, 2)}; }

// Whether the whole rectangle, with its margin, is blank paper: tested every 0.3 mm, finer than
// the card's finest print (a 0.7 mm outline).
bool blank_paper(const CardRect& r) {
  const CaptureCard& card = capture_card();
  for (double y = r.y0 - kPaperMarginMm; y <= r.y1 + kPaperMarginMm; y += 0.3)
    for (double x = r.x0 - kPaperMarginMm; x <= r.x1 + kPaperMarginMm; x += 0.3)
      if (card_reflectance({x, y}, false) != card.paper_reflectance) return false;
  return true;
}

// The paper cells of the card, computed once: the card does not change between photos.
const std::vector<CardRect>& paper_cells() {
  static const std::vector<CardRect> cells = [] {
    const CaptureCard& card = capture_card();
    const glm::dvec2 window = card.swatch_window.centre();
    std::vector<CardRect> out;
    for (double y = kPaperMarginMm; y + kPaperCellMm <= card.height - kPaperMarginMm; y += kPaperCellMm)
      for (double x = kPaperMarginMm; x + kPaperCellMm <= card.width - kPaperMarginMm; x += kPaperCellMm) {
        const CardRect r{x, y, x + kPaperCellMm, y + kPaperCellMm};
        // The cell's nearest point to the swatch's centre and to the ball's.
        auto nearest = [&](glm::dvec2 p) { return glm::length(glm::clamp(p, glm::dvec2(r.x0, r.y0), glm::dvec2(r.x1, r.y1)) - p); };
        if (nearest(window) < kSwatchCornerMm + kClearMm) continue;
        if (nearest(card.ball_centre) < card.ball_radius + kClearMm) continue;
        if (blank_paper(r)) out.push_back(r);
      }
    return out;
  }();
  return cells;
}

ResponseSample sample_rect(const Photo& p, const CardView& view, const CardRect& in, double reflectance) {
  const CaptureCard& card = capture_card();
  const glm::dvec3 ball = card_to_world(card.ball_centre) + glm::dvec3(0, 0, card.ball_radius / 1000.0);
  const double ball_r = card.ball_radius / 1000.0 * 1.02;  // and the ball's blurred rim
  ResponseSample s;
  s.reflectance = reflectance;
  const std::vector<glm::dvec3> corners{card_to_world({in.x0, in.y0}), card_to_world({in.x1, in.y0}),
                                        card_to_world({in.x1, in.y1}), card_to_world({in.x0, in.y1})};
  double r2 = 0;
  for_card_pixels(p, view, corners, [&](const glm::dvec3& w) { return in.contains(world_to_card(w)); },
                  [&](int x, int y, const glm::dvec3&) {
                    if (view.camera.sees_sphere(x + 0.5, y + 0.5, ball, ball_r)) return;
                    s.add(code_at(p, x, y));
                    r2 += image_radius2(p, x + 0.5, y + 0.5);
                  });
  // The mean over its pixels: the model's falloff is linear in r², so the mean is exact.
  s.r2 = s.count > 0 ? r2 / s.count : 0.0;
  return s;
}

}  // namespace

double image_radius2(const Photo& p, double x, double y) {
  return ((x - p.width / 2.0) * (x - p.width / 2.0) + (y - p.height / 2.0) * (y - p.height / 2.0)) /
         ((p.width * p.width + p.height * p.height) / 4.0);
}

std::vector<ResponseSample> card_response_samples(const Photo& photo, const CardView& view) {
  const CaptureCard& card = capture_card();
  std::vector<ResponseSample> samples;
  for (const GreyPatch& g : card.patches) {
    const CardRect in{g.rect.x0 + kPatchMarginMm, g.rect.y0 + kPatchMarginMm, g.rect.x1 - kPatchMarginMm, g.rect.y1 - kPatchMarginMm};
    samples.push_back(sample_rect(photo, view, in, g.reflectance));
  }
  for (const CardRect& r : paper_cells()) {
    ResponseSample s = sample_rect(photo, view, r, card.paper_reflectance);
    if (s.count >= kMinPixels) samples.push_back(std::move(s));
  }
  return samples;
}

}  // namespace weft
