#pragma once
// The printed capture card of `weft capture` (docs/capture.md): where its markers, grey patches,
// swatch window and mirror-ball spot lie, in millimetres on the paper (x right, y down from the
// card's top-left corner), and the card's world frame, in metres with +Z out of the paper
// (docs/design.md §3: the map's +Z is up when the card lies on a table):
//   X = x / 1000,  Y = (height − y) / 1000,  Z = 0.
// The photographer stands on the card's bottom edge (−Y) and shoots down at it.
//
// Markers: AprilTag tag36h11, ids 0–3 at the corners (clockwise from top-left), their black
// squares `tag_size` wide. Id 4, smaller, is printed on a strip below the card to be cut off
// and laid on the swatch with its image +x along the warp: its pose in each photo gives the
// swatch's turn. Id 5, tiny, is printed on the strip too, to be cut out and laid on the swatch
// for the close-up (capture/closeup_scale.h), its image +x along the warp: it gives the close-up's
// millimetres per pixel and the warp's direction. Six grey patches of known reflectance sit along
// the bottom edge.
#include <array>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

namespace weft {

struct CardRect {
  double x0, y0, x1, y1;  // mm
  bool contains(glm::dvec2 p) const { return p.x >= x0 && p.x < x1 && p.y >= y0 && p.y < y1; }
  glm::dvec2 centre() const { return {(x0 + x1) / 2, (y0 + y1) / 2}; }
};

struct CardTag {
  int id;
  glm::dvec2 centre;  // mm
  double size;        // the black square's side, mm (8 of the family's 10 cells)
};

struct GreyPatch {
  CardRect rect;
  double reflectance;  // diffuse, nominal: a printed card is measured once and these replaced
};

struct CaptureCard {
  double width = 250, height = 170;  // the card proper, mm (A4 landscape with the marker strip)
  double strip_height = 25;          // the cut-off strip below it that carries the swatch marker
  std::array<CardTag, 4> corner_tags{{{0, {22, 22}, 30}, {1, {228, 22}, 30}, {2, {228, 148}, 30}, {3, {22, 148}, 30}}};
  CardTag swatch_marker{4, {125, 182.5}, 12};  // as printed on the strip
  // 3 mm: a 10 mm close-up holds it beside the threads (0.3 mm cells: print at 600 dpi or more).
  CardTag closeup_tag{5, {165, 182.5}, 3};
  std::array<GreyPatch, 6> patches{{{{46, 135, 70, 160}, 0.04},
                                     {{73, 135, 97, 160}, 0.09},
                                     {{100, 135, 124, 160}, 0.18},
                                     {{127, 135, 151, 160}, 0.32},
                                     {{154, 135, 178, 160}, 0.52},
                                     {{181, 135, 205, 160}, 0.80}}};
  CardRect swatch_window{50, 20, 140, 110};
  double swatch_radius = 30;  // mm around the window's centre that every turn of a 70 mm swatch covers
  double marker_offset = 22;  // mm from the window's centre to the marker's, along the swatch's −weft
  glm::dvec2 ball_centre{180, 65};
  double ball_radius = 25;    // mm: a 50 mm chrome ball
  double paper_reflectance = 0.85, ink_reflectance = 0.04;
};

const CaptureCard& capture_card();

glm::dvec3 card_to_world(glm::dvec2 mm);
glm::dvec2 world_to_card(const glm::dvec3& p);

// The tag36h11 code `id` as the family renders it: 10×10 cells, true where black, row 0 at the
// top (cells outside the black square are the white border).
std::array<std::array<bool, 10>, 10> tag_cells(int id);

// What the card prints at paper point `mm` (swatch and ball not included): its diffuse
// reflectance, 0 outside the card and the strip.
double card_reflectance(glm::dvec2 mm, bool with_strip);
// Reflectance of a tag whose black square is centred at the origin, side `size`, at local `p`
// (mm, tag image axes): ink, paper, or −1 outside its 10-cell white border.
double tag_reflectance(int id, double size, glm::dvec2 p);

// The card with its strip at `dpi` as an 8-bit RGB PNG for printing (grey levels as sRGB codes of
// the nominal reflectances relative to the paper's).
void write_card_png(const std::filesystem::path& file, int dpi);

}  // namespace weft
