#include "capture/thread_counts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <numbers>

#include <Eigen/Dense>
#include <fftw3.h>

namespace weft {

namespace {

constexpr double kMinPerCm = 3.0, kMaxPerCm = 200.0;
constexpr double kMinPxPerYarn = 4.0;
constexpr double kMaxAngle = 8.0 * std::numbers::pi / 180.0;  // a hand-laid tag's error, with room
constexpr int kMinDiscPx = 64;
constexpr double kMinRepeats = 5.0;
constexpr double kStrongLine = 6.0;   // log power over the ring's median: 400 times
constexpr size_t kMaxLines = 16;
constexpr double kSidelobeReach = 4.0;  // lines (twice as many bins: the spectrum is zero-padded 2×)
constexpr double kSidelobeDrop = 3.0;   // log power
constexpr double kNearlyAll = 0.9;
constexpr double kCoarseSlack = 0.015;  // a 2 % step's drift of a lattice point, in its frequency
const double kMaxAspect = std::log(3.0);  // ends against picks: woven cloth stays within 3 : 1

struct Disc {
  glm::dvec2 centre{0.0};
  double radius = 0;
};

// The largest disc inside the frame that stays clear of the tag's paper (CloseupScale::covers's
// square), from centres on a 16-pixel grid.
Disc clear_disc(int width, int height, const CloseupScale& scale) {
  Disc best;
  for (int y = 0; y <= height; y += 16)
    for (int x = 0; x <= width; x += 16) {
      const glm::dvec2 c(x, y);
      const double r = std::min({c.x, c.y, width - c.x, height - c.y, glm::length(scale.outside_cover(c))});
      if (r > best.radius) best = {c, r};
    }
  return best;
}

// `v` turned by `angle` (radians, image axes).
glm::dvec2 rotated(glm::dvec2 v, double angle) {
  return {std::cos(angle) * v.x - std::sin(angle) * v.y, std::sin(angle) * v.x + std::cos(angle) * v.y};
}

// The share of the plane within `tolerance` of a lattice point whose cell has area `cell`: how
// often a line anywhere lies that near one by chance.
double chance(double tolerance, double cell) { return std::min(1.0, std::numbers::pi * tolerance * tolerance / cell); }

// FFTW's planner is not thread-safe; its plans' execution is.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

glm::dvec2 ThreadCounts::warp(glm::dvec2 tag_warp) const { return rotated(tag_warp, angle); }

double CloseupSpectrum::log_power_at(int kx, int ky) const {
  if (kx < 0) kx = -kx, ky = -ky;
  const int half = n / 2 + 1;
  if (kx >= half) return -1e30;
  return log_power[static_cast<size_t>((ky % n + n) % n) * half + kx];
}

std::optional<CloseupSpectrum> closeup_spectrum(const std::vector<double>& signal, const std::vector<bool>& use,
                                                int width, int height, const CloseupScale& scale) {
  const Disc disc = clear_disc(width, height, scale);
  if (disc.radius < kMinDiscPx || scale.px_per_mm <= 0) return std::nullopt;
  const int diameter = static_cast<int>(2 * disc.radius);
  CloseupSpectrum out;
  out.n = (2 * diameter + 31) / 32 * 32;
  out.px_per_mm = scale.px_per_mm;
  out.warp = scale.warp;
  out.disc_mm = diameter / scale.px_per_mm;
  const int n = out.n, half = n / 2 + 1;

  // The disc's values, their windowed mean removed, under the window.
  auto window = [&](int x, int y) {
    const double r = glm::length(glm::dvec2(x + 0.5, y + 0.5) - disc.centre) / disc.radius;
    return r < 1.0 ? 0.5 * (1.0 + std::cos(std::numbers::pi * r)) : 0.0;
  };
  const int x0 = static_cast<int>(disc.centre.x - disc.radius), y0 = static_cast<int>(disc.centre.y - disc.radius);
  const int xa = std::max(x0, 0), xb = std::min(x0 + diameter + 1, width);
  const int ya = std::max(y0, 0), yb = std::min(y0 + diameter + 1, height);
  double mean = 0, weight = 0;
  for (int y = ya; y < yb; ++y)
    for (int x = xa; x < xb; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      if (!use[i]) continue;
      const double w = window(x, y);
      mean += w * signal[i], weight += w;
    }
  if (weight <= 0) return std::nullopt;
  mean /= weight;
  double* in = fftw_alloc_real(static_cast<size_t>(n) * n);
  fftw_complex* spectrum = fftw_alloc_complex(static_cast<size_t>(n) * half);
  std::fill(in, in + static_cast<size_t>(n) * n, 0.0);
  for (int y = ya; y < yb; ++y)
    for (int x = xa; x < xb; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      if (use[i]) in[static_cast<size_t>(y - y0) * n + (x - x0)] = window(x, y) * (signal[i] - mean);
    }
  fftw_plan plan;
  {
    std::lock_guard lock(planner_mutex());
    plan = fftw_plan_dft_r2c_2d(n, n, in, spectrum, FFTW_ESTIMATE);
  }
  fftw_execute(plan);
  out.log_power.resize(static_cast<size_t>(n) * half);
  for (size_t i = 0; i < out.log_power.size(); ++i) {
    const double p = spectrum[i][0] * spectrum[i][0] + spectrum[i][1] * spectrum[i][1];
    out.log_power[i] = static_cast<float>(std::log(std::max(p, 1e-300)));
  }
  {
    std::lock_guard lock(planner_mutex());
    fftw_destroy_plan(plan);
  }
  fftw_free(in);
  fftw_free(spectrum);
  // Each bin over the median of its ring (one bin wide): a photo's power falls with frequency
  // (the light's slopes, the lens), and only what stands above its own ring is a line.
  const int rings = static_cast<int>(std::ceil(std::sqrt(2.0) * half)) + 1;
  std::vector<std::vector<float>> ring(rings);
  auto ring_of = [&](size_t i) {
    const int ky = static_cast<int>(i / half), kx = static_cast<int>(i % half);
    return static_cast<int>(std::lround(std::hypot(kx, ky <= n / 2 ? ky : ky - n)));
  };
  for (size_t i = 0; i < out.log_power.size(); ++i) ring[ring_of(i)].push_back(out.log_power[i]);
  std::vector<float> median(rings, 0.0f);
  for (int r = 0; r < rings; ++r)
    if (!ring[r].empty()) {
      std::nth_element(ring[r].begin(), ring[r].begin() + ring[r].size() / 2, ring[r].end());
      median[r] = ring[r][ring[r].size() / 2];
    }
  for (size_t i = 0; i < out.log_power.size(); ++i) out.log_power[i] -= median[ring_of(i)];
  return out;
}

ThreadCounts weave_counts(const CloseupSpectrum& s, int rows, int shift) {
  ThreadCounts out;
  if (s.n == 0 || rows < 1) return out;
  out.resolution_per_cm = 10.0 / s.disc_mm;
  const double px_per_cm = 10.0 * s.px_per_mm;
  // At least kMinRepeats yarns across the disc.
  const double c_lo = std::max(kMinPerCm / px_per_cm, kMinRepeats / (s.disc_mm * s.px_per_mm));
  const double c_hi = std::min(kMaxPerCm / px_per_cm, 1.0 / kMinPxPerYarn);  // per pixel
  if (c_hi <= c_lo) return out;

  // The strong lines: local maxima standing kStrongLine over their ring, from two lines out to
  // twice the finest count searched, the strongest kMaxLines, each centred by a parabola.
  const int n = s.n;
  const double bin = 1.0 / n;
  auto value = [&](int kx, int ky) { return s.log_power_at(kx, ky); };
  struct Line {
    glm::dvec2 k;
    double weight;
  };
  std::vector<Line> lines;
  const int reach = std::min(n / 2 - 1, static_cast<int>(2.0 * c_hi * n));
  for (int ky = -reach; ky <= reach; ++ky)
    for (int kx = 0; kx <= reach; ++kx) {
      if (kx == 0 && ky <= 0) continue;  // one of each ± pair
      const double r = std::hypot(kx, ky);
      if (r < 2.0 || r > reach) continue;
      const double v = value(kx, ky);
      if (v < kStrongLine) continue;
      bool peak = true;
      for (int dy = -1; dy <= 1 && peak; ++dy)
        for (int dx = -1; dx <= 1 && peak; ++dx)
          if ((dx || dy) && value(kx + dx, ky + dy) > v) peak = false;
      if (!peak) continue;
      auto offset = [](double minus, double centre, double plus) {
        const double d = minus - 2 * centre + plus;
        return d < 0 ? std::clamp(0.5 * (minus - plus) / d, -0.5, 0.5) : 0.0;
      };
      const glm::dvec2 k(kx + offset(value(kx - 1, ky), v, value(kx + 1, ky)), ky + offset(value(kx, ky - 1), v, value(kx, ky + 1)));
      lines.push_back({k * bin, v});
    }
  // A strong line's window sidelobes (2–3 lines out, 31 dB down) are local maxima too: a line
  // within kSidelobeReach lines of one kSidelobeDrop stronger is dropped.
  std::sort(lines.begin(), lines.end(), [](const Line& x, const Line& y) { return x.weight > y.weight; });
  std::vector<Line> peaks;
  for (const Line& l : lines) {
    bool sidelobe = false;
    for (const Line& k : peaks)
      sidelobe = sidelobe || (k.weight - l.weight >= kSidelobeDrop && glm::length(k.k - l.k) <= 2.0 * kSidelobeReach * bin);
    if (!sidelobe) peaks.push_back(l);
  }
  lines = peaks;
  // The lowest: a yarn's sharp edges keep its harmonics strong far out, where a lattice 2 % off
  // is a whole line off.
  std::sort(lines.begin(), lines.end(), [](const Line& x, const Line& y) { return glm::length(x.k) < glm::length(y.k); });
  if (lines.size() > kMaxLines) lines.resize(kMaxLines);
  out.points = static_cast<int>(lines.size());
  if (lines.size() < 3) return out;
  double total = 0;
  for (const Line& l : lines) total += l.weight;

  // A line is on a lattice point within 1.5 bins and `slack` of its frequency (a coarse lattice's
  // step drifts its points in proportion).
  auto tolerance = [&](const Line& l, double slack) { return 1.5 * bin + slack * glm::length(l.k); };
  // The floats' diagonal runs one way or its mirror (a satin's face from its back, the photo's
  // handedness against the file's): both are tried.
  int sign = 1;
  // The share of the lines' weight on the lattice of (e, p, angle), less chance's share (a dense
  // lattice explains any lines).
  auto explained = [&](double e, double p, double angle, double slack) {
    const double shift_along = sign * static_cast<double>(shift);
    const glm::dvec2 a = rotated(s.warp, angle), b(-a.y, a.x);
    double sum = 0;
    for (const Line& l : lines) {
      const double along = glm::dot(l.k, a), across = glm::dot(l.k, b);
      const double m = std::round(along / (p / rows));
      const double nn = std::round(across / e + m * shift_along / rows);
      const glm::dvec2 point = (m * p / rows) * a + e * (nn - m * shift_along / rows) * b;
      if (glm::length(l.k - point) <= tolerance(l, slack)) sum += l.weight;
      sum -= l.weight * chance(tolerance(l, slack), e * p / rows);
    }
    return sum / total;
  };
  // Coarse: 2 % steps in each count, half a degree in the angle, a line explained within the
  // step's drift. The weave is the coarsest lattice (the largest counts) that explains nearly as
  // much as the best: every finer lattice (a fraction of the counts) explains as much, a multiple
  // misses the fundamental lines.
  const double step = std::log(1.02);
  struct Candidate {
    double e, p, angle, explained;
    int sign;
  };
  std::vector<Candidate> candidates;
  double best = 0;
  for (sign = 1; sign >= -1; sign -= 2)
  for (double le = std::log(c_lo); le <= std::log(c_hi); le += step)
    for (double lp = std::max(std::log(c_lo), le - kMaxAspect); lp <= std::min(std::log(c_hi), le + kMaxAspect); lp += step)
      for (double angle = -kMaxAngle; angle <= kMaxAngle + 1e-9; angle += std::numbers::pi / 360.0) {
        const double v = explained(std::exp(le), std::exp(lp), angle, kCoarseSlack);
        if (v > 0.5) candidates.push_back({std::exp(le), std::exp(lp), angle, v, sign});
        best = std::max(best, v);
      }
  if (candidates.empty()) return out;
  const Candidate* chosen = nullptr;
  for (const Candidate& c : candidates)
    if (c.explained >= kNearlyAll * best && (!chosen || c.e * c.p > chosen->e * chosen->p * 1.0001 ||
                                             (std::abs(c.e * c.p / (chosen->e * chosen->p) - 1) < 1e-4 && c.explained > chosen->explained)))
      chosen = &c;
  // Fine: each line given its lattice indices (m, n) by the chosen lattice, the basis G₁, G₂ in
  // image axes by least squares over k_i = m_i·G₁ + n_i·G₂, weighted by the lines' strength; lines
  // more than a bin off (a sidelobe, an alias of a harmonic past the pixels' Nyquist) are dropped
  // and the basis solved again.
  sign = chosen->sign;
  const double shift_along = sign * static_cast<double>(shift);
  const glm::dvec2 a0 = rotated(s.warp, chosen->angle), b0(-a0.y, a0.x);
  glm::dvec2 g1 = (chosen->p / rows) * a0 - (chosen->e * shift_along / rows) * b0, g2 = chosen->e * b0;
  std::vector<std::array<double, 2>> index(lines.size());
  std::vector<bool> kept(lines.size(), false);
  const double det = g1.x * g2.y - g1.y * g2.x;
  for (size_t i = 0; i < lines.size(); ++i) {
    // Solve k = m·G₁ + n·G₂ for (m, n) and round.
    const double m = (lines[i].k.x * g2.y - lines[i].k.y * g2.x) / det, nn = (g1.x * lines[i].k.y - g1.y * lines[i].k.x) / det;
    index[i] = {std::round(m), std::round(nn)};
    const glm::dvec2 d = lines[i].k - (index[i][0] * g1 + index[i][1] * g2);
    kept[i] = glm::length(d) <= tolerance(lines[i], kCoarseSlack);
  }
  for (int round = 0; round < 3; ++round) {
    Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
    Eigen::Matrix<double, 2, 2> rhs = Eigen::Matrix2d::Zero();  // columns: x, y of k
    int used = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
      if (!kept[i]) continue;
      const Eigen::Vector2d mn(index[i][0], index[i][1]);
      normal += lines[i].weight * mn * mn.transpose();
      rhs.col(0) += lines[i].weight * mn * lines[i].k.x;
      rhs.col(1) += lines[i].weight * mn * lines[i].k.y;
      ++used;
    }
    if (used < 3 || std::abs(normal.determinant()) < 1e-12 * normal.squaredNorm()) break;
    const Eigen::Matrix2d basis = normal.ldlt().solve(rhs);  // rows: G₁, G₂
    g1 = {basis(0, 0), basis(0, 1)}, g2 = {basis(1, 0), basis(1, 1)};
    for (size_t i = 0; i < lines.size(); ++i)
      kept[i] = kept[i] && glm::length(lines[i].k - (index[i][0] * g1 + index[i][1] * g2)) <= bin;
  }
  // Back to counts: G₂ = e·b, G₁ = (p / rows)·a − (e·shift / rows)·b.
  const glm::dvec2 b = glm::normalize(g2), a(b.y, -b.x);
  out.ends_per_cm = glm::length(g2) * px_per_cm;
  out.picks_per_cm = std::abs(glm::dot(g1, a)) * rows * px_per_cm;
  const glm::dvec2 warp = glm::dot(a, s.warp) < 0 ? -a : a;
  out.angle = std::atan2(s.warp.x * warp.y - s.warp.y * warp.x, glm::dot(s.warp, warp));
  out.score = chosen->explained;
  double on = 0;
  const double cell = std::abs(g1.x * g2.y - g1.y * g2.x);  // the lattice's area per point
  for (size_t i = 0; i < lines.size(); ++i) {
    if (kept[i]) ++out.fitted_lines, on += lines[i].weight;
    on -= lines[i].weight * chance(bin, std::max(cell, 1e-300));
  }
  out.fitted_share = on / total;
  return out;
}

}  // namespace weft
