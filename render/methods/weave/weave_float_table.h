#pragma once
// The weave layer's per-float lighting, kept per vertex (methods/weave/weave_ratio.h): at a
// vertex, each thread's resolved response (R's numerator) averaged over each of kWeaveTableArcs
// cells along its float, as weave_float_response averages a pixel's part of a float (cut at the
// curve's jumps, three arcs a stretch). Read at the cells' centres and interpolated linearly in
// between, the table keeps each float's mean exactly. A pixel then
// reads its floats' shading off the table interpolated from its triangle's vertices, where the
// per-pixel layer loops over every light for every float: the per-pixel work no longer grows with
// the lights, and the lights' work grows with the vertices the frame shows, not with its pixels.
// Over a per-vertex rung the fabric-level terms are interpolated from the vertices anyway; the
// table is interpolated the same way, so the factor keeps taking the rung's interpolation out.
// C++ twin of weave_float_table.glsl.
#include <array>
#include <span>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "core/weave_coverage.h"
#include "core/weave_layout.h"
#include "methods/weave/weave_ratio.h"

namespace weft {

// Cells along each float. A float's shading changes along it as its tilt does: a satin's warp
// float turns through ~60° over its length, its highlight a tenth of it. Against the exact
// per-pixel shading where a pixel holds half a thread, 8 cells were 15.6 % off pixel by pixel on
// the satin and 11.7 % on the velvet, 12 cells 7.4 % and 7.3 %, 16 cells 4.8 % and 6.6 %
// (weave_float_table_test); 12 cells are 72 values a vertex, 18 packed vec4 varyings with the
// layer's own two: within the 32 of a desktop or llvmpipe GL, beyond GLES 3.0's minimum of 15
// (a GL with fewer shows the fabric level up close, with a warning).
inline constexpr int kWeaveTableArcs = 12;

// Node m of a float: the centre of its m-th cell, (m + ½)/kWeaveTableArcs.
double weave_table_arc(int m);

// Thread j's node m at table[j·kWeaveTableArcs + m].
using WeaveFloatTable = std::array<dvec3, 2 * kWeaveTableArcs>;

// Node m of thread j as a pixel's coverage: the cell its one piece, seen uniformly.
WeaveCoverage weave_table_cell(int thread, int m);

// The table at a point: `terms` are the point's fabric-level terms (weave_terms), `sgs` the
// layer's lights.
WeaveFloatTable weave_float_table(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, const WeaveTerms& terms,
                                  std::span<const SphericalGaussian> sgs);

// Thread j's response at `arc` along its float: linear between the nodes, the end nodes' beyond them.
dvec3 weave_table_at(const WeaveFloatTable& table, int thread, double arc);

// R over a pixel's footprint (tile-space derivatives dx, dy) from the table, over `fabric`: the
// layout box-filtered over it, every float in it (for_each_weave_float: a lookup costs too little
// to keep only the largest) averaged over its arc range at three Gauss–Legendre points, each
// weighted by the footprint's density there.
dvec3 weave_ratio_tabled(const WeaveLayout& layout, const WeaveFloatTable& table, glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy,
                         const dvec3& fabric);

}  // namespace weft
