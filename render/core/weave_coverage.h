#pragma once
// The weave layout (core/weave_layout.h) box-filtered over one pixel: how much of the pixel each
// thread covers, and where along its float, so that a yarn's edge covers a pixel in part as it
// does in a supersampled image, for one shading evaluation per float present. The pixel's
// footprint is the parallelogram st ± ½dx ± ½dy (tile-space derivatives across one pixel); its
// weight along s and along t is each a box of |dx|'s component convolved with a box of |dy|'s
// (exact for the parallelogram's marginals), and a rectangle of the layout (one float) gets the
// product of its two marginal masses. A pixel on a row's edge holds floats of the same thread at
// different places along them (a satin's neighbouring warp floats are half a float apart), so the
// few largest floats are kept apart, each with its own arc. C++ twin of weave_coverage() in
// methods/weave/weave_layout.glsl.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "core/weave_layout.h"

namespace weft {

// The floats a pixel's shading visits, largest first: a footprint of a thread or less holds one or
// two of each thread, four where it straddles a float's corner; up to two threads a pixel (where
// the layer still draws at all) the smaller floats' share goes to the kept ones (piece_weight).
inline constexpr int kWeaveCoveragePieces = 4;

// One float's part of the pixel.
struct WeavePiece {
  int thread = -1;     // 0 warp, 1 weft; −1 an unused slot
  double share = 0.0;  // of the pixel
  double arc = 0.0;    // along the float, at the middle of its overlap with the footprint's box
  // The overlap's ends along the float (arc_lo ≤ arc ≤ arc_hi), and the footprint's centre in
  // the float's arc (beyond [0, 1] where the centre lies off the float): where along the float
  // the pixel sees it, weighted by the footprint's marginal (arc_density).
  double arc_lo = 0.0, arc_hi = 0.0, centre = 0.0;
};

struct WeaveCoverage {
  double share[2] = {0.0, 0.0};  // of the pixel, per thread (warp, weft); the rest is gap
  // The largest floats in the pixel, largest first; a thread's share beyond its kept floats is
  // spread over them in proportion (piece_weight), so that each thread keeps its whole share.
  WeavePiece piece[kWeaveCoveragePieces];
  // RMS spread of arc over the footprint along each thread's float (its marginal along s for the
  // warp, along t for the weft, in fractions of the float): the tilts a pixel mixes.
  double arc_spread[2] = {0.0, 0.0};
  // The footprint's two box widths along each thread's float, in arc: its marginal along the
  // float is a box of the first convolved with a box of the second.
  double arc_box[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
};

// The footprint's density along piece p's float at arc x (per unit arc): the box pair of
// c.arc_box[p.thread] centred at p.centre.
double arc_density(const WeaveCoverage& c, const WeavePiece& p, double x);

// Rows and floats farther than this from the footprint's centre are not visited: the layer fades
// the weave out by two threads a pixel (methods/weave/weave_ratio.h), so where it is drawn at all
// a footprint reaches at most a thread, a row, either side of its centre; a float starts at most
// one float before the one under the centre.
inline constexpr int kWeaveCoverageReach = 2;

// The mass in [lo, hi] of a box of width a convolved with a box of width b, both centred at 0
// (the footprint's marginal along one axis); widths may be 0 (a step).
double box_pair_mass(double lo, double hi, double a, double b);
// Its density at x (0 where both widths are 0).
double box_pair_density(double x, double a, double b);

WeaveCoverage weave_coverage(const WeaveLayout& layout, glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy);

// The footprint's two box widths along each thread's float, in arc (WeaveCoverage::arc_box).
struct WeaveArcBoxes {
  double box[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
};
WeaveArcBoxes weave_arc_boxes(const WeaveLayout& layout, glm::dvec2 dx, glm::dvec2 dy);

// Calls visit(piece) for every float with a share of the footprint (rows and floats within
// kWeaveCoverageReach of its centre), in no particular order: what weave_coverage keeps the
// largest of, and what a shading cheap enough to visit every float sums (weave_float_table.h).
template <class Visit>
void for_each_weave_float(const WeaveLayout& layout, glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, Visit&& visit);

namespace detail {
// Float j over the rectangle [s0, s1] × [t0, t1] of the footprint centred at c (box widths a, b,
// half-extent half); arc_at gives its arc at (s, t). share 0: not in the footprint.
template <class ArcAt>
WeavePiece weave_float_piece(int j, double s0, double s1, double t0, double t1, glm::dvec2 c, glm::dvec2 a, glm::dvec2 b,
                             glm::dvec2 half, ArcAt arc_at) {
  WeavePiece p;
  p.share = box_pair_mass(s0 - c.x, s1 - c.x, a.x, b.x) * box_pair_mass(t0 - c.y, t1 - c.y, a.y, b.y);
  if (p.share <= 0.0) return p;
  const double s_lo = std::max(s0, c.x - half.x), s_hi = std::min(s1, c.x + half.x);
  const double t_lo = std::max(t0, c.y - half.y), t_hi = std::min(t1, c.y + half.y);
  p.thread = j;
  p.arc = std::clamp(arc_at(0.5 * (s_lo + s_hi), 0.5 * (t_lo + t_hi)), 0.0, 1.0);
  p.arc_lo = std::clamp(arc_at(s_lo, t_lo), 0.0, 1.0);
  p.arc_hi = std::clamp(arc_at(s_hi, t_hi), 0.0, 1.0);
  p.centre = arc_at(c.x, c.y);
  return p;
}
}  // namespace detail

template <class Visit>
void for_each_weave_float(const WeaveLayout& layout, glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, Visit&& visit) {
  const double w = layout.yarn_width(), f = layout.warp_share();
  if (w <= 0.0) return;
  const double rows = layout.rows();
  const glm::dvec2 c = st - glm::floor(st);  // the tile's own coordinates keep precision
  const glm::dvec2 a = glm::abs(dx), b = glm::abs(dy);
  const glm::dvec2 half = 0.5 * (a + b);
  const int kc = int(std::floor(c.y * rows));
  const int k0 = std::max(int(std::floor((c.y - half.y) * rows)), kc - kWeaveCoverageReach);
  const int k1 = std::min(int(std::floor((c.y + half.y) * rows)), kc + kWeaveCoverageReach);
  for (int k = k0; k <= k1; ++k) {
    const int row = ((k % layout.rows()) + layout.rows()) % layout.rows();
    const double o = double(row * layout.shift()) / rows;
    const double t0 = k / rows, t1 = (k + 1) / rows;
    const int mc = int(std::floor(c.x - o));
    const int m0 = std::max(int(std::floor(c.x - half.x - o)) - 1, mc - kWeaveCoverageReach);
    const int m1 = std::min(int(std::floor(c.x + half.x - o)), mc + kWeaveCoverageReach);
    for (int m = m0; m <= m1; ++m) {
      const double s = o + m;
      // The warp floats over [s, s + f) in the middle w of the row.
      const WeavePiece warp = detail::weave_float_piece(0, s, s + f, t0 + (0.5 - 0.5 * w) / rows, t0 + (0.5 + 0.5 * w) / rows, c,
                                                        a, b, half, [&](double sm, double) { return f > 0.0 ? (sm - s) / f : 0.0; });
      if (warp.share > 0.0) visit(warp);
      // The weft crosses the whole row in the middle w of the rest.
      const double g0 = s + f + (1.0 - f) * (0.5 - 0.5 * w), g1 = s + f + (1.0 - f) * (0.5 + 0.5 * w);
      const WeavePiece weft =
          detail::weave_float_piece(1, g0, g1, t0, t1, c, a, b, half, [&](double, double tm) { return (tm - t0) * rows; });
      if (weft.share > 0.0) visit(weft);
    }
  }
}

// The weight of piece i in the pixel's shading: its thread's share × its part of that thread's
// kept pieces; 0 for an unused slot. The weights sum to share[0] + share[1].
double piece_weight(const WeaveCoverage& c, int i);


}  // namespace weft
