#include "capture/closeup_registration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "capture/card_samples.h"
#include "capture/float_radiance.h"
#include "core/weave_layout.h"

namespace weft {

namespace {

constexpr int kClipCode = 250;
constexpr int kMaxBinsPerThread = 16;
constexpr int kMinBinsPerThread = 4;
constexpr int kArcBins = 128;    // along each float, as the close-up's simulator draws it
constexpr int kTangentSamples = 32;  // the tangent quadrature of the model's Q, as the simulator's default
constexpr int kSubsamples = 4;   // per side of a bin: a yarn's edge is a partial bin
constexpr int kUnknowns = 10;    // k, B_warp (RGB), B_weft (RGB), g (RGB)

// The tile's bins, row t by column s, cyclic.
struct Tile {
  int ns = 0, nt = 0;
  size_t index(int s, int t) const {
    return static_cast<size_t>(((t % nt) + nt) % nt) * ns + static_cast<size_t>(((s % ns) + ns) % ns);
  }
  size_t size() const { return static_cast<size_t>(ns) * nt; }
};

// Bins no pixel fell in take their neighbours' mean (a lattice whose period is a whole number of
// pixels visits only some bins), so that every bin holds a value and a cyclic shift of the
// prediction keeps its own normal matrix.
void fill_empty(const Tile& tile, std::vector<glm::dvec3>& value, std::vector<long>& count) {
  for (int round = 0; round < tile.ns + tile.nt; ++round) {
    bool empty = false;
    std::vector<glm::dvec3> next = value;
    std::vector<long> filled = count;
    for (int t = 0; t < tile.nt; ++t)
      for (int s = 0; s < tile.ns; ++s) {
        const size_t i = tile.index(s, t);
        if (count[i] > 0) continue;
        glm::dvec3 sum(0);
        int n = 0;
        for (const auto& [ds, dt] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}})
          if (const size_t k = tile.index(s + ds, t + dt); count[k] > 0) sum += value[k], ++n;
        if (n > 0) {
          next[i] = sum / static_cast<double>(n);
          filled[i] = 1;
        } else {
          empty = true;
        }
      }
    value.swap(next);
    count.swap(filled);
    if (!empty) return;
  }
}

}  // namespace

CloseupRegistration register_closeup(const Photo& photo, const ResponseModel& response, const CloseupScale& scale,
                                     const ThreadCounts& counts, const Fabric& fabric, const std::vector<FitLight>& lights,
                                     double turn) {
  CloseupRegistration out;
  if (!counts.candidate() || counts.ends_per_cm <= 0 || counts.picks_per_cm <= 0 || scale.px_per_mm <= 0 || lights.empty()) {
    out.why = "the lattice is not resolved, nor a candidate";
    return out;
  }
  const WeaveLayout layout(fabric);
  const int rows = layout.rows();
  const double px_per_cm = 10.0 * scale.px_per_mm;
  const double end_px = px_per_cm / counts.ends_per_cm, pick_px = px_per_cm / counts.picks_per_cm;
  const int per_thread = std::clamp(static_cast<int>(std::min(end_px, pick_px)), kMinBinsPerThread, kMaxBinsPerThread);
  const Tile tile{rows * per_thread, rows * per_thread};
  out.tile_bins = {tile.ns, tile.nt};
  // The warp's image direction, the lattice's own (the tag's turned by the fitted angle); the weft
  // at right angles to it, one way or the mirror.
  const glm::dvec2 a = counts.warp(scale.warp), b(-a.y, a.x);
  const double repeat_s = rows * pick_px, repeat_t = rows * end_px;  // pixels

  // The folded tile, both handednesses in one pass over the pixels.
  std::array<std::vector<glm::dvec3>, 2> fold{std::vector<glm::dvec3>(tile.size(), glm::dvec3(0)),
                                              std::vector<glm::dvec3>(tile.size(), glm::dvec3(0))};
  std::array<std::vector<long>, 2> hits{std::vector<long>(tile.size(), 0), std::vector<long>(tile.size(), 0)};
  const glm::dvec2 centre(0.5 * photo.width, 0.5 * photo.height);
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      const glm::dvec2 p(x + 0.5, y + 0.5);
      if (scale.covers(p)) continue;
      const std::array<std::uint8_t, 3> code{photo.at(x, y, 0), photo.at(x, y, 1), photo.at(x, y, 2)};
      if (std::max({code[0], code[1], code[2]}) >= kClipCode) continue;
      const glm::dvec3 v = response.relative(code, image_radius2(photo, p.x, p.y));
      const double s = glm::dot(p - centre, a) / repeat_s, t = glm::dot(p - centre, b) / repeat_t;
      const int is = static_cast<int>(std::floor((s - std::floor(s)) * tile.ns));
      for (int h = 0; h < 2; ++h) {
        const double th = h ? -t : t;
        const size_t i = tile.index(is, static_cast<int>(std::floor((th - std::floor(th)) * tile.nt)));
        fold[h][i] += v;
        ++hits[h][i];
      }
      ++out.pixels;
    }
  if (out.pixels < static_cast<long>(tile.size()) * 4) {
    out.why = "too few pixels to fold into the weave's tile";
    return out;
  }
  for (int h = 0; h < 2; ++h) {
    for (size_t i = 0; i < tile.size(); ++i)
      if (hits[h][i] > 0) fold[h][i] /= static_cast<double>(hits[h][i]);
    fill_empty(tile, fold[h], hits[h]);
  }

  // The model's parts along each thread's float straight above: the surface's (no albedo), and the
  // volume's per unit albedo (the radiance is linear in A).
  Fabric clear = fabric, white = fabric;
  for (int j = 0; j < 2; ++j) clear.threads[j].albedo = glm::dvec3(0), white.threads[j].albedo = glm::dvec3(1);
  const FloatRadiance surface = float_radiance(clear, lights, turn, kArcBins, kTangentSamples);
  FloatRadiance volume = float_radiance(white, lights, turn, kArcBins, kTangentSamples);
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < kArcBins; ++k) volume[j][k] -= surface[j][k];
  // The prediction's columns at phase 0, per bin and channel: S, V_warp, V_weft, G.
  struct Parts {
    glm::dvec3 s{0.0}, v0{0.0}, v1{0.0};
    double gap = 0;
    std::array<double, 2> share{};  // of each thread
  };
  std::vector<Parts> parts(tile.size());
  for (int t = 0; t < tile.nt; ++t)
    for (int s = 0; s < tile.ns; ++s) {
      Parts& q = parts[tile.index(s, t)];
      constexpr double kWeight = 1.0 / (kSubsamples * kSubsamples);
      for (int u = 0; u < kSubsamples; ++u)
        for (int w = 0; w < kSubsamples; ++w) {
          const WeaveSample at = layout.at((s + (u + 0.5) / kSubsamples) / tile.ns, (t + (w + 0.5) / kSubsamples) / tile.nt);
          if (at.thread < 0) {
            q.gap += kWeight;
            continue;
          }
          const int k = arc_bin(at.arc, kArcBins);
          q.s += kWeight * surface[at.thread][k];
          q.share[at.thread] += kWeight;
          (at.thread == 0 ? q.v0 : q.v1) += kWeight * volume[at.thread][k];
        }
    }
  // Column c of the design at bin i, channel ch (unknowns: k, B_warp RGB, B_weft RGB, g RGB).
  auto column = [&](const Parts& q, int c, int ch) {
    if (c == 0) return q.s[ch];
    if (c <= 3) return c - 1 == ch ? q.v0[ch] : 0.0;
    if (c <= 6) return c - 4 == ch ? q.v1[ch] : 0.0;
    return c - 7 == ch ? q.gap : 0.0;
  };
  // AᵀA is the same at every phase (a cyclic shift of every column): once, a little ridge for a
  // column the weave leaves empty (no gaps).
  Eigen::Matrix<double, kUnknowns, kUnknowns> normal = Eigen::Matrix<double, kUnknowns, kUnknowns>::Zero();
  for (const Parts& q : parts)
    for (int ch = 0; ch < 3; ++ch) {
      Eigen::Matrix<double, kUnknowns, 1> row;
      for (int c = 0; c < kUnknowns; ++c) row[c] = column(q, c, ch);
      normal += row * row.transpose();
    }
  normal.diagonal().array() += 1e-9 * normal.diagonal().maxCoeff();
  const Eigen::Matrix<double, kUnknowns, kUnknowns> inverse = normal.inverse();

  // Every phase (a whole bin of shift) and handedness: Aᵀb by correlation, the residual from it.
  const size_t shifts = tile.size();
  std::vector<double> explained(2 * shifts, 0.0);
  std::array<double, 2> variance{};
  for (int h = 0; h < 2; ++h) {
    glm::dvec3 mean(0);
    for (const glm::dvec3& o : fold[h]) mean += o;
    mean /= static_cast<double>(tile.size());
    for (const glm::dvec3& o : fold[h]) variance[h] += glm::dot(o - mean, o - mean);
  }
  std::array<double, 2> total{};  // bᵀb
  for (int h = 0; h < 2; ++h)
    for (const glm::dvec3& o : fold[h]) total[h] += glm::dot(o, o);
  auto projection = [&](int h, int ds, int dt) {
    Eigen::Matrix<double, kUnknowns, 1> atb = Eigen::Matrix<double, kUnknowns, 1>::Zero();
    for (int t = 0; t < tile.nt; ++t)
      for (int s = 0; s < tile.ns; ++s) {
        const glm::dvec3& o = fold[h][tile.index(s, t)];
        const Parts& q = parts[tile.index(s + ds, t + dt)];
        atb[0] += glm::dot(q.s, o);
        for (int ch = 0; ch < 3; ++ch) {
          atb[1 + ch] += q.v0[ch] * o[ch];
          atb[4 + ch] += q.v1[ch] * o[ch];
          atb[7 + ch] += q.gap * o[ch];
        }
      }
    return atb;
  };
#pragma omp parallel for schedule(static)
  for (long i = 0; i < static_cast<long>(2 * shifts); ++i) {
    const int h = static_cast<int>(i / shifts), shift = static_cast<int>(i % shifts);
    const auto atb = projection(h, shift % tile.ns, shift / tile.ns);
    const double residual = total[h] - atb.dot(inverse * atb);
    explained[i] = variance[h] > 0 ? 1.0 - residual / variance[h] : 0.0;
  }
  const size_t best = static_cast<size_t>(std::max_element(explained.begin(), explained.end()) - explained.begin());
  std::vector<double> sorted = explained;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  out.explained = explained[best];
  out.explained_median = sorted[sorted.size() / 2];
  const int h = static_cast<int>(best / shifts), shift = static_cast<int>(best % shifts);
  out.mirrored = h == 1;
  out.phase = {static_cast<double>(shift % tile.ns) / tile.ns, static_cast<double>(shift / tile.ns) / tile.nt};
  const Eigen::Matrix<double, kUnknowns, 1> x = inverse * projection(h, shift % tile.ns, shift / tile.ns);
  out.exposure = x[0];
  for (int ch = 0; ch < 3; ++ch) {
    out.albedo[0][ch] = x[1 + ch];
    out.albedo[1][ch] = x[4 + ch];
  }
  if (out.exposure > 0) out.albedo[0] /= out.exposure, out.albedo[1] /= out.exposure;
  char why[200] = "";
  const double least = 1e-3 * std::max({x[1], x[2], x[3], x[4], x[5], x[6]});
  if (out.explained < CloseupRegistration::kMinExplained)
    std::snprintf(why, sizeof why, "the weave's model explains %.0f %% of the folded tile (under %.0f %%)", 100 * out.explained,
                  100 * CloseupRegistration::kMinExplained);
  else if (out.explained - out.explained_median < CloseupRegistration::kMinPhaseGain)
    std::snprintf(why, sizeof why, "no phase stands out (%.0f %% explained against %.0f %% at the median phase)", 100 * out.explained,
                  100 * out.explained_median);
  // A surface term or a colour that comes out negative is the solve trading S against V_j (broad
  // lobes leave them alike straight above), not a wrong phase: the phase and each thread's mean
  // hold (a random shot silk's registered ratio within 1 % of its colour clusters' at an exposure
  // of −1.1), its albedos do not.
  out.albedo_read = out.exposure > 0 && least > 0 && std::min({x[1], x[2], x[3], x[4], x[5], x[6]}) >= least;
  out.why = why;
  out.registered = why[0] == 0;
  // Each thread's mean over the bins the registered weave fills with it alone, and with it alone
  // all round (a yarn's edge mixes the lens's blur and the phase's last half bin): the means the
  // fit's resolved model is held to, whatever the lobes the photos fitted make of them.
  std::array<glm::dvec3, 2> sum{glm::dvec3(0), glm::dvec3(0)};
  const int ds = shift % tile.ns, dt = shift / tile.ns;
  auto alone = [&](int s, int t, int j) { return parts[tile.index(s + ds, t + dt)].share[j] > 0.999; };
  for (int t = 0; t < tile.nt; ++t)
    for (int s = 0; s < tile.ns; ++s)
      for (int j = 0; j < 2; ++j)
        if (alone(s, t, j) && alone(s - 1, t, j) && alone(s + 1, t, j) && alone(s, t - 1, j) && alone(s, t + 1, j)) {
          sum[j] += fold[h][tile.index(s, t)];
          ++out.inner_bins[j];
        }
  for (int j = 0; j < 2; ++j) out.thread_mean[j] = out.inner_bins[j] > 0 ? sum[j] / static_cast<double>(out.inner_bins[j]) : glm::dvec3(0);
  if (out.registered && (out.inner_bins[0] == 0 || out.inner_bins[1] == 0)) {
    out.registered = false;
    out.why = "a thread fills no bin of the tile by itself";
  } else if (out.registered && glm::any(glm::lessThanEqual(glm::min(out.thread_mean[0], out.thread_mean[1]), glm::dvec3(0)))) {
    out.registered = false;
    out.why = "a thread reads black in a channel where the weave puts it";
  }
  if (least > 0)
    for (int ch = 0; ch < 3; ++ch) out.albedo_ratio[ch] = std::max(x[1 + ch], least) / std::max(x[4 + ch], least);
  return out;
}

}  // namespace weft
