#pragma once
// The card's known reflectances read from one photo, as samples for the response calibration
// (response_calibration.h): the six grey patches, and blank paper in a grid of cells over the
// whole card, so that the vignetting has samples from the image's centre to the card's corners.
// Paper cells keep clear of every print, of everywhere a turned swatch can reach, and of the
// ball; pixels where the ball hides the card from the camera are left out.
#include <vector>

#include <glm/glm.hpp>

#include "capture/card_detection.h"
#include "capture/photo_files.h"
#include "capture/response_calibration.h"

namespace weft {

// Squared distance of image point (x, y) from the image centre over the half diagonal.
double image_radius2(const Photo& p, double x, double y);

// Calls visit(x, y, world) for every pixel whose centre maps into the card region `inside`
// (world point → bool), within the image box of `corners` (world).
template <class Inside, class Visit>
void for_card_pixels(const Photo& p, const CardView& view, const std::vector<glm::dvec3>& corners, Inside inside, Visit visit) {
  glm::dvec2 lo(1e30), hi(-1e30);
  for (const auto& c : corners) {
    const glm::dvec2 q = view.to_image(c);
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const int x0 = std::max(0, static_cast<int>(lo.x)), x1 = std::min(p.width, static_cast<int>(hi.x) + 1);
  const int y0 = std::max(0, static_cast<int>(lo.y)), y1 = std::min(p.height, static_cast<int>(hi.y) + 1);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const glm::dvec3 w = view.to_world({x + 0.5, y + 0.5});
      if (inside(w)) visit(x, y, w);
    }
}

// The patches first (capture_card.h's order), then the paper cells that the photo shows.
std::vector<ResponseSample> card_response_samples(const Photo& photo, const CardView& view);

}  // namespace weft
