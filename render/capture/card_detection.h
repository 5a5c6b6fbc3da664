#pragma once
// Finding the card in a photo: its AprilTags (libapriltag, tag36h11), the homography from the
// card's plane to the image, the camera's pose, the swatch marker's turn, and how sharp the
// photo is. Rectification reads the card's regions back through the homography: each image pixel
// whose centre maps into a region belongs to it.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "capture/card_camera.h"
#include "capture/photo_files.h"

namespace weft {

struct TagSighting {
  int id = -1;
  std::array<glm::dvec2, 4> corners;  // image positions, in the detector's order
  double decision_margin = 0;
};

std::vector<TagSighting> detect_tags(const Photo& photo);

struct CardView {
  glm::dmat3 H{1.0};       // card plane (world X, Y in metres, 1) → image (homogeneous)
  CardCamera camera;
  int corner_tags = 0;     // of the four
  double reprojection_rms = 0;  // px, the corner tags' corners through H
  std::optional<double> marker_turn;  // the swatch's warp angle in world, radians, when id 4 is seen
  glm::dvec3 marker_centre{0.0};      // world
  double edge_width = 0;   // median 10–90 % width of the tags' outer edges, px
  bool focal_estimated = false;

  glm::dvec2 to_image(const glm::dvec3& world) const;
  glm::dvec3 to_world(const glm::dvec2& image) const;  // on the card's plane
};

// The card in `photo`, or a CaptureRejection naming `what` (fewer than two corner tags). The focal
// length comes from capture.json, or is estimated from the homography.
CardView locate_card(const Photo& photo, std::optional<double> focal_px, const std::string& what);

}  // namespace weft
