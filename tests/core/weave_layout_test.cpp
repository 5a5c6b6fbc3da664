// The resolved weave's layout against what docs/design.md §2 asks of it: thread j covers a_j of
// the repeat, its float runs along the curve uniformly in arc length, the tile repeats, and the
// repeat's average of the resolved integrand is the fabric-level integrand (the canonical model
// averaged, for every preset and a spread of directions).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/cloth_bsdf.h"
#include "core/fabric.h"
#include "core/weave_layout.h"

using namespace weft;
using glm::dvec3;

static const std::filesystem::path kFabrics = std::filesystem::path(WEFT_SOURCE_ASSETS) / "fabrics";

TEST(WeaveLayout, ThreadsCoverTheirShareAndRunUniformlyAlongTheirCurves) {
  constexpr int kGrid = 600, kBins = 6;
  for (const std::string& name : list_fabric_presets(kFabrics)) {
    const Fabric f = load_fabric_preset(name, kFabrics);
    const WeaveLayout layout(f);
    std::array<double, 2> share{};
    std::array<std::array<double, kBins>, 2> arcs{};
    for (int y = 0; y < kGrid; ++y)
      for (int x = 0; x < kGrid; ++x) {
        const WeaveSample w = layout.at((x + 0.5) / kGrid, (y + 0.5) / kGrid);
        if (w.thread < 0) continue;
        ASSERT_GE(w.arc, 0.0);
        ASSERT_LT(w.arc, 1.0);
        ASSERT_LE(std::abs(w.across), 0.5);
        share[w.thread] += 1.0 / (kGrid * kGrid);
        arcs[w.thread][int(w.arc * kBins)] += 1.0 / (kGrid * kGrid);
      }
    for (int j = 0; j < 2; ++j) {
      const double a = f.threads[j].coverage;
      EXPECT_NEAR(share[j], a, 0.01) << name << " thread " << j;
      for (int b = 0; b < kBins; ++b) EXPECT_NEAR(arcs[j][b], a / kBins, 0.01) << name << " thread " << j << " bin " << b;
    }
  }
}

TEST(WeaveLayout, RepeatsWithPeriodOneAndPlainWeaveAlternates) {
  const Fabric linen = load_fabric_preset("linen_plain", kFabrics);
  const WeaveLayout layout(linen);
  EXPECT_EQ(layout.rows(), 2);
  for (double s : {0.1, 0.37, 0.8})
    for (double t : {0.05, 0.25, 0.6}) {
      const WeaveSample a = layout.at(s, t), b = layout.at(s + 3.0, t - 2.0);
      EXPECT_EQ(a.thread, b.thread);
      EXPECT_NEAR(a.arc, b.arc, 1e-9);
    }
  // A plain weave: the warp floats where the weft shows in the next row (a checkerboard).
  EXPECT_EQ(layout.at(0.25, 0.25).thread, 0);
  EXPECT_EQ(layout.at(0.75, 0.75).thread, 0);
  EXPECT_EQ(layout.at(0.75, 0.25).thread, 1);
  EXPECT_EQ(layout.at(0.25, 0.75).thread, 1);
  // Satin: long warp floats, five rows, weft showing in a scattered fifth.
  const WeaveLayout satin(load_fabric_preset("polyester_satin_charmeuse", kFabrics));
  EXPECT_EQ(satin.rows(), 5);
  EXPECT_NEAR(satin.warp_share(), 0.9, 1e-12);
}

TEST(WeaveLayout, RepeatAverageOfResolvedIntegrandIsTheFabricLevelIntegrand) {
  constexpr int kGrid = 200;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto upper = [&] {
    for (;;) {
      const dvec3 w(u(rng), u(rng), u(rng));
      const double l = glm::length(w);
      if (l > 0.2 && l < 1.0 && w.z / l > 0.1) return w / l;
    }
  };
  for (const std::string& name : list_fabric_presets(kFabrics)) {
    const Fabric f = load_fabric_preset(name, kFabrics);
    const WeaveLayout layout(f);
    const ClothBsdf bsdf(f, 256);
    SurfaceFrame frame;
    ClothBsdf::Point point = bsdf.at(frame);
    double err2 = 0.0, ref2 = 0.0;
    for (int pair = 0; pair < 12; ++pair) {
      const dvec3 wi = upper(), wo = upper();
      dvec3 avg(0.0);
      // Q is the fabric's, the same at every point of the repeat: resolved_integrand is this over it.
      const double q = point.q(wi, wo);
      if (q <= kQFloor) {  // W = 0 everywhere: both sides are zero
        EXPECT_EQ(point.integrand(wi, wo), dvec3(0.0));
        EXPECT_EQ(point.resolved_integrand(0, 0.1, wi, wo), dvec3(0.0));
        continue;
      }
      const dvec3 one = point.resolved_integrand(0, 0.1, wi, wo);
      EXPECT_LT(glm::length(one - point.resolved_scattering(0, 0.1, wi, wo) / q), 1e-12 * (1.0 + glm::length(one)));
      for (int y = 0; y < kGrid; ++y)
        for (int x = 0; x < kGrid; ++x) {
          const WeaveSample w = layout.at((x + 0.5) / kGrid, (y + 0.5) / kGrid);
          if (w.thread < 0) continue;
          avg += point.resolved_scattering(w.thread, weave_tilt(f, w), wi, wo) / q;
        }
      avg /= double(kGrid) * kGrid;
      const dvec3 fabric_level = point.integrand(wi, wo);
      err2 += glm::dot(avg - fabric_level, avg - fabric_level);
      ref2 += glm::dot(fabric_level, fabric_level);
    }
    ASSERT_GT(ref2, 0.0) << name;
    EXPECT_LT(std::sqrt(err2 / ref2), 0.01) << name;
  }
}

TEST(WeaveLayout, FabricFileGivesTheWeaveAndRejectsNonsense) {
  const std::string threads =
      R"("threads": [{"eta": 1.46, "albedo": [1,1,1], "albedo_scale": 0.3, "kd": 0.3, "gamma_s_deg": 12, "gamma_v_deg": 24,
      "coverage": 0.4, "tangent_offsets_deg": [-20, 20], "segment_lengths": [1]},
      {"eta": 1.46, "albedo": [1,1,1], "albedo_scale": 0.3, "kd": 0.3, "gamma_s_deg": 12, "gamma_v_deg": 24,
      "coverage": 0.4, "tangent_offsets_deg": [0], "segment_lengths": []}])";
  auto with = [&](const std::string& weave) { return "{\"name\": \"t\", " + threads + ", \"weave\": " + weave + "}"; };
  const Fabric f = parse_fabric(with(R"({"rows": 3, "shift": 1, "ends_per_cm": 40, "picks_per_cm": 20})"), "t.json");
  EXPECT_EQ(f.weave.rows, 3);
  EXPECT_EQ(f.weave.shift, 1);
  const glm::dvec2 repeat = weave_repeat_cm(f);
  EXPECT_DOUBLE_EQ(repeat.x, 3.0 / 20.0);
  EXPECT_DOUBLE_EQ(repeat.y, 3.0 / 40.0);
  for (const char* bad : {R"({"rows": 0})", R"({"rows": 2.5})", R"({"shift": 1})", R"({"rows": 4, "shift": 4})",
                          R"({"ends_per_cm": 0})", R"({"picks_per_cm": -3})", R"({"threads": 3})", R"([1, 2])"}) {
    try {
      parse_fabric(with(bad), "t.json");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const FabricError& e) {
      EXPECT_NE(std::string(e.what()).find("weave"), std::string::npos) << e.what();
    }
  }
}
