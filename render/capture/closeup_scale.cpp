#include "capture/closeup_scale.h"

#include <cmath>

#include "capture/capture_card.h"
#include "capture/card_detection.h"

namespace weft {

glm::dvec2 CloseupScale::in_tag_axes(glm::dvec2 p) const {
  // The detector's corners 0→1 along the tag's +x.
  const glm::dvec2 across(-warp.y, warp.x), d = p - centre;
  return {glm::dot(d, warp), glm::dot(d, across)};
}

glm::dvec2 CloseupScale::outside_cover(glm::dvec2 p) const {
  const double half = 0.5 * kCoverGrowth * capture_card().closeup_tag.size * px_per_mm;
  return glm::max(glm::abs(in_tag_axes(p)) - half, glm::dvec2(0.0));
}

std::optional<CloseupScale> find_closeup_scale(const Photo& photo) {
  const CardTag& tag = capture_card().closeup_tag;
  for (const TagSighting& t : detect_tags(photo)) {
    if (t.id != tag.id) continue;
    CloseupScale s;
    double side = 0;
    for (int k = 0; k < 4; ++k) {
      s.centre += 0.25 * t.corners[k];
      side += 0.25 * glm::length(t.corners[(k + 1) % 4] - t.corners[k]);
    }
    // From straight above the square stays a square: its +x is the mean of its two x edges.
    const glm::dvec2 x = (t.corners[1] - t.corners[0]) + (t.corners[2] - t.corners[3]);
    if (side <= 0 || glm::length(x) <= 0) continue;
    s.warp = glm::normalize(x);
    s.px_per_mm = side / tag.size;
    return s;
  }
  return std::nullopt;
}

}  // namespace weft
