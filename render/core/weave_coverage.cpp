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

WeaveCoverage weave_coverage(const WeaveLayout& layout, glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy) {
  WeaveCoverage out;
  const double w = layout.yarn_width(), f = layout.warp_share();
  if (w <= 0.0) return out;
  const double rows = layout.rows();
  const glm::dvec2 c = st - glm::floor(st);  // the tile's own coordinates keep precision
  const glm::dvec2 a = glm::abs(dx), b = glm::abs(dy);
  const glm::dvec2 half = 0.5 * (a + b);
  // A box of width a convolved with one of width b has variance (a² + b²)/12.
  out.arc_spread[0] = f > 0.0 ? std::sqrt((a.x * a.x + b.x * b.x) / 12.0) / f : 0.0;
  out.arc_spread[1] = std::sqrt((a.y * a.y + b.y * b.y) / 12.0) * rows;
  if (f > 0.0) out.arc_box[0][0] = a.x / f, out.arc_box[0][1] = b.x / f;
  out.arc_box[1][0] = a.y * rows, out.arc_box[1][1] = b.y * rows;
  // One rectangle [s0, s1] × [t0, t1] of thread j: the arc of its float at s or t (arc_at).
  auto piece = [&](int j, double s0, double s1, double t0, double t1, auto arc_at) {
    const double share = box_pair_mass(s0 - c.x, s1 - c.x, a.x, b.x) * box_pair_mass(t0 - c.y, t1 - c.y, a.y, b.y);
    if (share <= 0.0) return;
    out.share[j] += share;
    // Insertion into the kept pieces, largest first; the smallest falls off the end.
    int i = kWeaveCoveragePieces;
    while (i > 0 && share > out.piece[i - 1].share) --i;
    if (i == kWeaveCoveragePieces) return;
    for (int k = kWeaveCoveragePieces - 1; k > i; --k) out.piece[k] = out.piece[k - 1];
    const double s_lo = std::max(s0, c.x - half.x), s_hi = std::min(s1, c.x + half.x);
    const double t_lo = std::max(t0, c.y - half.y), t_hi = std::min(t1, c.y + half.y);
    WeavePiece& p = out.piece[i];
    p = WeavePiece{j, share, std::clamp(arc_at(0.5 * (s_lo + s_hi), 0.5 * (t_lo + t_hi)), 0.0, 1.0)};
    p.arc_lo = std::clamp(arc_at(s_lo, t_lo), 0.0, 1.0);
    p.arc_hi = std::clamp(arc_at(s_hi, t_hi), 0.0, 1.0);
    p.centre = arc_at(c.x, c.y);
  };
  const int k0 = int(std::floor((c.y - half.y) * rows)), k1 = int(std::floor((c.y + half.y) * rows));
  for (int k = std::max(k0, int(std::floor(c.y * rows)) - kWeaveCoverageReach);
       k <= std::min(k1, int(std::floor(c.y * rows)) + kWeaveCoverageReach); ++k) {
    const int row = ((k % layout.rows()) + layout.rows()) % layout.rows();
    const double o = double(row * layout.shift()) / rows;
    const double t0 = k / rows, t1 = (k + 1) / rows;
    const int m0 = int(std::floor(c.x - half.x - o)) - 1, m1 = int(std::floor(c.x + half.x - o));
    const int mc = int(std::floor(c.x - o));
    for (int m = std::max(m0, mc - kWeaveCoverageReach); m <= std::min(m1, mc + kWeaveCoverageReach); ++m) {
      const double s = o + m;
      // The warp floats over [s, s + f) in the middle w of the row.
      piece(0, s, s + f, t0 + (0.5 - 0.5 * w) / rows, t0 + (0.5 + 0.5 * w) / rows,
            [&](double sm, double) { return f > 0.0 ? (sm - s) / f : 0.0; });
      // The weft crosses the whole row in the middle w of the rest.
      const double g0 = s + f + (1.0 - f) * (0.5 - 0.5 * w), g1 = s + f + (1.0 - f) * (0.5 + 0.5 * w);
      piece(1, g0, g1, t0, t1, [&](double, double tm) { return (tm - t0) * rows; });
    }
  }
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
