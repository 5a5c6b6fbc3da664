#include "methods/weave/weave_float_table.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace weft {

double weave_table_arc(int m) { return (m + 0.5) / kWeaveTableArcs; }

WeaveFloatTable weave_float_table(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, const WeaveTerms& terms,
                                  std::span<const SphericalGaussian> sgs) {
  std::vector<HorizonLight> lights;
  for (const auto& g : sgs) lights.push_back(horizon_light(g, frame.n));
  WeaveFloatTable table;
  for (int j = 0; j < 2; ++j)
    for (int m = 0; m < kWeaveTableArcs; ++m) {
      const WeaveCoverage cell = weave_table_cell(j, m);
      table[size_t(j * kWeaveTableArcs + m)] = weave_float_response(bsdf, frame, wo, cell, 0, terms, sgs, lights);
    }
  return table;
}

WeaveCoverage weave_table_cell(int thread, int m) {
  constexpr double width = 1.0 / kWeaveTableArcs;
  WeaveCoverage c;
  c.share[thread] = 1.0;
  c.piece[0] = WeavePiece{thread, 1.0, weave_table_arc(m), m * width, (m + 1) * width, weave_table_arc(m)};
  c.arc_box[thread][0] = width;  // uniform over the cell
  c.arc_spread[thread] = width / std::sqrt(12.0);
  return c;
}

dvec3 weave_table_at(const WeaveFloatTable& table, int thread, double arc) {
  const double x = std::clamp(arc * kWeaveTableArcs - 0.5, 0.0, double(kWeaveTableArcs - 1));
  const int m = std::min(int(x), kWeaveTableArcs - 2);
  const size_t base = size_t(thread * kWeaveTableArcs + m);
  return glm::mix(table[base], table[base + 1], x - m);
}

dvec3 weave_ratio_tabled(const WeaveLayout& layout, const WeaveFloatTable& table, glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy,
                         const dvec3& fabric) {
  constexpr double kNode = 0.7745966692414834, kWeights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  const WeaveArcBoxes boxes = weave_arc_boxes(layout, dx, dy);
  dvec3 resolved(0.0);
  for_each_weave_float(layout, st, dx, dy, [&](const WeavePiece& p) {
    const double* box = boxes.box[p.thread];
    dvec3 sum(0.0);
    double total = 0.0;
    const double mid = 0.5 * (p.arc_lo + p.arc_hi), half = 0.5 * (p.arc_hi - p.arc_lo);
    if (half > 0.0)
      for (int m = 0; m < 3; ++m) {
        const double a = mid + (m - 1) * kNode * half, w = kWeights[m] * half * box_pair_density(a - p.centre, box[0], box[1]);
        if (w <= 0.0) continue;
        sum += w * weave_table_at(table, p.thread, a);
        total += w;
      }
    resolved += p.share * (total > 0.0 ? sum / total : weave_table_at(table, p.thread, p.arc));
  });
  return weave_ratio_of(resolved, fabric);
}

}  // namespace weft
