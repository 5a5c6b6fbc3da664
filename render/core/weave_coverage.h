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

WeaveCoverage weave_coverage(const WeaveLayout& layout, glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy);

// The weight of piece i in the pixel's shading: its thread's share × its part of that thread's
// kept pieces; 0 for an unused slot. The weights sum to share[0] + share[1].
double piece_weight(const WeaveCoverage& c, int i);

// The mass in [lo, hi] of a box of width a convolved with a box of width b, both centred at 0
// (the footprint's marginal along one axis); widths may be 0 (a step).
double box_pair_mass(double lo, double hi, double a, double b);
// Its density at x (0 where both widths are 0).
double box_pair_density(double x, double a, double b);

}  // namespace weft
