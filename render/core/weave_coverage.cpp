#include "core/weave_coverage.h"

#include <algorithm>
#include <cmath>

namespace weft {

namespace {
constexpr double kNarrow = 1e-12;  // a box narrower than this is a step

// ∫_{-∞}^{y} of the CDF of a box of width a centred at 0.
double box_cdf_integral(double y, double a) {
  if (a < kNarrow) return std::max(y, 0.0);
  const double z = y / a + 0.5;
  if (z <= 0.0) return 0.0;
  return a * (z < 1.0 ? 0.5 * z * z : z - 0.5);
}

// The CDF at x of a box of width a convolved with one of width b.
double box_pair_cdf(double x, double a, double b) {
  if (a < b) std::swap(a, b);
  if (b < kNarrow) return a < kNarrow ? (x >= 0.0 ? 1.0 : 0.0) : std::clamp(x / a + 0.5, 0.0, 1.0);
  return (box_cdf_integral(x + 0.5 * b, a) - box_cdf_integral(x - 0.5 * b, a)) / b;
}
}  // namespace

double box_pair_mass(double lo, double hi, double a, double b) {
  return hi <= lo ? 0.0 : std::max(box_pair_cdf(hi, a, b) - box_pair_cdf(lo, a, b), 0.0);
}

double box_pair_density(double x, double a, double b) {
  if (a < b) std::swap(a, b);
  if (a < kNarrow) return 0.0;
  auto box_cdf = [&](double y) { return std::clamp(y / a + 0.5, 0.0, 1.0); };
  if (b < kNarrow) return std::abs(x) < 0.5 * a ? 1.0 / a : 0.0;
  return (box_cdf(x + 0.5 * b) - box_cdf(x - 0.5 * b)) / b;
}

double arc_density(const WeaveCoverage& c, const WeavePiece& p, double x) {
  return p.thread < 0 ? 0.0 : box_pair_density(x - p.centre, c.arc_box[p.thread][0], c.arc_box[p.thread][1]);
}

WeaveArcBoxes weave_arc_boxes(const WeaveLayout& layout, glm::dvec2 dx, glm::dvec2 dy) {
  WeaveArcBoxes out;
  const double f = layout.warp_share();
  const glm::dvec2 a = glm::abs(dx), b = glm::abs(dy);
  if (f > 0.0) out.box[0][0] = a.x / f, out.box[0][1] = b.x / f;
  out.box[1][0] = a.y * layout.rows(), out.box[1][1] = b.y * layout.rows();
  return out;
}

WeaveCoverage weave_coverage(const WeaveLayout& layout, glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy) {
  WeaveCoverage out;
  if (layout.yarn_width() <= 0.0) return out;
  const double f = layout.warp_share(), rows = layout.rows();
  const glm::dvec2 a = glm::abs(dx), b = glm::abs(dy);
  // A box of width a convolved with one of width b has variance (a² + b²)/12.
  out.arc_spread[0] = f > 0.0 ? std::sqrt((a.x * a.x + b.x * b.x) / 12.0) / f : 0.0;
  out.arc_spread[1] = std::sqrt((a.y * a.y + b.y * b.y) / 12.0) * rows;
  const WeaveArcBoxes boxes = weave_arc_boxes(layout, dx, dy);
  for (int j = 0; j < 2; ++j) out.arc_box[j][0] = boxes.box[j][0], out.arc_box[j][1] = boxes.box[j][1];
  for_each_weave_float(layout, st, dx, dy, [&](const WeavePiece& p) {
    out.share[p.thread] += p.share;
    // Insertion into the kept pieces, largest first; the smallest falls off the end.
    int i = kWeaveCoveragePieces;
    while (i > 0 && p.share > out.piece[i - 1].share) --i;
    if (i == kWeaveCoveragePieces) return;
    for (int k = kWeaveCoveragePieces - 1; k > i; --k) out.piece[k] = out.piece[k - 1];
    out.piece[i] = p;
  });
  return out;
}

double piece_weight(const WeaveCoverage& c, int i) {
  const WeavePiece& p = c.piece[i];
  if (p.thread < 0) return 0.0;
  double kept = 0.0;
  for (const auto& q : c.piece)
    if (q.thread == p.thread) kept += q.share;
  return c.share[p.thread] * p.share / kept;
}

}  // namespace weft
