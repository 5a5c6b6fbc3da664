#pragma once
// The close-up's scale tag (capture_card.h: id 5, 3 mm, laid on the swatch with its image +x
// along the warp): millimetres per pixel, the warp's direction in the frame, and the pixels the
// tag and its paper cover, which are not the swatch.
#include <optional>

#include <glm/glm.hpp>

#include "capture/photo_files.h"

namespace weft {

struct CloseupScale {
  glm::dvec2 centre{0.0};     // the black square's, image pixels
  glm::dvec2 warp{1.0, 0.0};  // unit image direction of the tag's +x: the warp's
  double px_per_mm = 0;
  // The square the tag and its paper cover: the black square grown to kCoverGrowth times its side
  // (the white border is 1.25, the rest is the paper's cut edge and the lens's blur).
  static constexpr double kCoverGrowth = 1.4;
  // Image point `p` from the black square's centre along the tag's +x and its +y, pixels.
  glm::dvec2 in_tag_axes(glm::dvec2 p) const;
  // How far image point `p` lies outside that square along the tag's two axes (0 within it).
  glm::dvec2 outside_cover(glm::dvec2 p) const;
  bool covers(glm::dvec2 p) const { return outside_cover(p) == glm::dvec2(0.0); }
};

// The scale tag in a close-up, or nothing when it is not there (or not decoded).
std::optional<CloseupScale> find_closeup_scale(const Photo& photo);

}  // namespace weft
