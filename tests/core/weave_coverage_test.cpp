// The layout box-filtered over a pixel (core/weave_coverage.h) against the pixel supersampled
// finely (WeaveLayout::at on a 96×96 grid over the footprint's parallelogram): each thread's share,
// and where along its floats it lies, for every preset's layout, footprints from a fortieth of a repeat to a thread across, aligned
// with the weave (where the product of the marginals is the exact box filter) and turned.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "core/fabric.h"
#include "core/weave_coverage.h"

using namespace weft;
using glm::dvec2;

static const std::filesystem::path kFabrics = std::filesystem::path(WEFT_SOURCE_ASSETS) / "fabrics";

namespace {
// Each thread's share of the parallelogram st ± ½dx ± ½dy, supersampled.
std::array<double, 2> supersampled_shares(const WeaveLayout& layout, dvec2 st, dvec2 dx, dvec2 dy) {
  constexpr int kN = 96;
  std::array<double, 2> share{};
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const dvec2 p = st + ((i + 0.5) / kN - 0.5) * dx + ((j + 0.5) / kN - 0.5) * dy;
      const WeaveSample w = layout.at(p.x, p.y);
      if (w.thread >= 0) share[w.thread] += 1.0 / (kN * kN);
    }
  return share;
}
}  // namespace

TEST(WeaveCoverage, AlignedFootprintsGetTheSupersampledShares) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const std::string& name : list_fabric_presets(kFabrics)) {
    const WeaveLayout layout(load_fabric_preset(name, kFabrics));
    const double thread = 1.0 / layout.rows();
    for (int i = 0; i < 200; ++i) {
      const dvec2 st(u(rng) * 3.0 - 1.0, u(rng) * 3.0 - 1.0);
      const dvec2 dx(thread * (0.025 + 0.975 * u(rng)), 0.0), dy(0.0, thread * (0.025 + 0.975 * u(rng)));
      const WeaveCoverage c = weave_coverage(layout, st, dx, dy);
      const auto expect = supersampled_shares(layout, st, dx, dy);
      for (int j = 0; j < 2; ++j) EXPECT_NEAR(c.share[j], expect[j], 0.025) << name << " at " << st.x << ", " << st.y;
    }
  }
}

TEST(WeaveCoverage, TurnedFootprintsStayCloseToTheSupersampledShares) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const WeaveLayout layout(load_fabric_preset("linen_plain", kFabrics));
  const double thread = 1.0 / layout.rows();
  double err2 = 0.0;
  constexpr int kCases = 300;
  for (int i = 0; i < kCases; ++i) {
    const double turn = u(rng) * 3.14159265, size = thread * (0.05 + 0.2 * u(rng));
    const dvec2 st(u(rng), u(rng));
    const dvec2 dx = size * dvec2(std::cos(turn), std::sin(turn)), dy = size * dvec2(-std::sin(turn), std::cos(turn));
    const WeaveCoverage c = weave_coverage(layout, st, dx, dy);
    const auto expect = supersampled_shares(layout, st, dx, dy);
    for (int j = 0; j < 2; ++j) err2 += (c.share[j] - expect[j]) * (c.share[j] - expect[j]) / (2.0 * kCases);
  }
  EXPECT_LT(std::sqrt(err2), 0.05);
  RecordProperty("rms_share_error", std::to_string(std::sqrt(err2)));
  std::cout << "turned footprints: RMS share error " << std::sqrt(err2) << "\n";
}

TEST(WeaveCoverage, KeepsEachThreadsShareOfTheRepeat) {
  for (const std::string& name : list_fabric_presets(kFabrics)) {
    const Fabric f = load_fabric_preset(name, kFabrics);
    const WeaveLayout layout(f);
    constexpr int kN = 64;
    std::array<double, 2> mean{};
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        const WeaveCoverage c = weave_coverage(layout, {(i + 0.5) / kN, (j + 0.5) / kN}, {0.13, 0.02}, {-0.03, 0.11});
        for (int t = 0; t < 2; ++t) mean[t] += c.share[t] / (kN * kN);
      }
    for (int t = 0; t < 2; ++t) EXPECT_NEAR(mean[t], f.threads[t].coverage, 0.01) << name << " thread " << t;
  }
}

TEST(WeaveCoverage, ATinyFootprintIsThePointUnderIt) {
  const WeaveLayout layout(load_fabric_preset("polyester_satin_charmeuse", kFabrics));
  for (double x = 0.013; x < 1.0; x += 0.07)
    for (double y = 0.021; y < 1.0; y += 0.09) {
      const WeaveSample w = layout.at(x, y);
      const WeaveCoverage c = weave_coverage(layout, {x, y}, {1e-7, 0.0}, {0.0, 1e-7});
      for (int j = 0; j < 2; ++j) EXPECT_NEAR(c.share[j], w.thread == j ? 1.0 : 0.0, 1e-3) << x << ", " << y;
      if (w.thread >= 0) {
        EXPECT_EQ(c.piece[0].thread, w.thread);
        EXPECT_NEAR(c.piece[0].arc, w.arc, 1e-5);
        EXPECT_NEAR(piece_weight(c, 0), 1.0, 1e-3);
      }
    }
}

// A footprint across a row's edge holds two floats of one thread at different places along them
// (a satin's neighbouring warp floats are half a float apart): the pieces' weighted arcs give the
// supersampled pixel's mean of a function of the arc, which one arc per thread cannot.
TEST(WeaveCoverage, PiecesKeepEachFloatsPlaceAlongIt) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // A smooth function of the arc that tells the two ends of a float apart.
  auto g = [](double arc) { return std::cos(2.0 * arc) + arc * arc; };
  for (const std::string& name : list_fabric_presets(kFabrics)) {
    const WeaveLayout layout(load_fabric_preset(name, kFabrics));
    const double thread = 1.0 / layout.rows();
    double err2 = 0.0, one2 = 0.0;
    int cases = 0;
    for (int i = 0; i < 300; ++i) {
      const dvec2 st(u(rng) * 2.0, u(rng) * 2.0);
      const dvec2 dx(thread * (0.1 + 0.4 * u(rng)), 0.0), dy(0.0, thread * (0.1 + 0.9 * u(rng)));
      const WeaveCoverage c = weave_coverage(layout, st, dx, dy);
      constexpr int kN = 96;
      double expect = 0.0;
      for (int b = 0; b < kN; ++b)
        for (int a = 0; a < kN; ++a) {
          const dvec2 p = st + ((a + 0.5) / kN - 0.5) * dx + ((b + 0.5) / kN - 0.5) * dy;
          const WeaveSample w = layout.at(p.x, p.y);
          if (w.thread >= 0) expect += g(w.arc) / (kN * kN);
        }
      double got = 0.0, largest_only = 0.0;
      for (int k = 0; k < kWeaveCoveragePieces; ++k) got += piece_weight(c, k) * g(c.piece[k].arc);
      // One arc per thread, its largest float's: what the pieces replace.
      for (int j = 0; j < 2; ++j)
        for (const auto& p : c.piece)
          if (p.thread == j) {
            largest_only += c.share[j] * g(p.arc);
            break;
          }
      err2 += (got - expect) * (got - expect);
      one2 += (largest_only - expect) * (largest_only - expect);
      ++cases;
    }
    const double rms = std::sqrt(err2 / cases), rms_one = std::sqrt(one2 / cases);
    std::cout << name << ": RMS error of the arc mean " << rms << " (one arc per thread: " << rms_one << ")\n";
    EXPECT_LT(rms, 0.015) << name;
  }
}

// Where along a float the pixel sees it: the piece's arc range holds every supersampled point of
// that float, and the footprint's density over the range (arc_density) has the points' mean arc.
TEST(WeaveCoverage, EachFloatsArcRangeAndDensityMatchTheSupersampledPoints) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (const std::string& name : list_fabric_presets(kFabrics)) {
    const WeaveLayout layout(load_fabric_preset(name, kFabrics));
    const double thread = 1.0 / layout.rows();
    for (int i = 0; i < 100; ++i) {
      const dvec2 st(u(rng) * 3.0 - 1.0, u(rng) * 3.0 - 1.0);
      const dvec2 dx(thread * (0.05 + 0.95 * u(rng)), 0.0), dy(0.0, thread * (0.05 + 0.95 * u(rng)));
      const WeaveCoverage c = weave_coverage(layout, st, dx, dy);
      for (int j = 0; j < 2; ++j) {
        // Only a thread with one float in the pixel: its supersampled points are all of that float.
        int piece = -1, pieces = 0;
        for (int k = 0; k < kWeaveCoveragePieces; ++k)
          if (c.piece[k].thread == j) piece = k, ++pieces;
        if (pieces != 1 || c.share[j] < 0.05) continue;
        const WeavePiece& p = c.piece[piece];
        EXPECT_LE(p.arc_lo, p.arc);
        EXPECT_LE(p.arc, p.arc_hi);
        constexpr int kN = 96;
        double sum = 0.0, n = 0.0, lowest = 1.0, highest = 0.0;
        for (int y = 0; y < kN; ++y)
          for (int x = 0; x < kN; ++x) {
            const dvec2 q = st + ((x + 0.5) / kN - 0.5) * dx + ((y + 0.5) / kN - 0.5) * dy;
            const WeaveSample w = layout.at(q.x, q.y);
            if (w.thread != j) continue;
            sum += w.arc, n += 1.0;
            lowest = std::min(lowest, w.arc), highest = std::max(highest, w.arc);
          }
        // The range within a supersample's step of the points' own.
        const double step = (j == 0 ? dx.x / layout.warp_share() : dy.y * layout.rows()) / kN;
        EXPECT_LE(p.arc_lo, lowest + 1e-9) << name;
        EXPECT_GE(p.arc_hi, highest - 1e-9) << name;
        EXPECT_NEAR(p.arc_lo, lowest, 1.5 * step) << name;
        EXPECT_NEAR(p.arc_hi, highest, 1.5 * step) << name;
        // The density's mean arc over the range, by the midpoint rule.
        double mass = 0.0, moment = 0.0;
        for (int m = 0; m < 1000; ++m) {
          const double a = p.arc_lo + (m + 0.5) / 1000.0 * (p.arc_hi - p.arc_lo), d = arc_density(c, p, a);
          mass += d, moment += d * a;
        }
        ASSERT_GT(mass, 0.0) << name;
        EXPECT_NEAR(moment / mass, sum / n, 0.01 + step) << name;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 300);
}
