// Choosing bake settings from an error target: each choice is the cheapest candidate whose
// measured error meets the target, and tighter targets never choose cheaper settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "bake/tables/bake_selection.h"
#include "core/fabric.h"

using namespace weft;

static Fabric preset(const std::string& name) { return load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics"); }

// Small probe: fast, and enough to separate 1 sample from many on a satin's floats.
static TangentProbe small_probe() {
  TangentProbe p;
  p.xi_resolution = 6;
  p.wo_resolution = 6;
  p.wi_resolution = 24;
  p.lambda = 32.0;
  p.converged_samples = 16;
  p.candidates = {1, 2, 4, 8, 16};
  return p;
}

TEST(TangentSampleSelection, ErrorVanishesAtTheReferenceAndShrinksWithSamples) {
  const Fabric f = preset("polyester_satin_charmeuse");
  const TangentProbe p = small_probe();
  EXPECT_EQ(tangent_sample_error(f, {16, 16}, {16, 16}, p), 0.0);
  const double e1 = tangent_sample_error(f, {1, 16}, {16, 16}, p);
  const double e8 = tangent_sample_error(f, {8, 16}, {16, 16}, p);
  EXPECT_GT(e1, 0.01);  // one straight sample misses the satin's tilted floats
  EXPECT_LT(e8, e1);
}

TEST(TangentSampleSelection, ChoosesTheFirstCandidateMeetingTheTargetAndIsMonotone) {
  const Fabric f = preset("polyester_satin_charmeuse");
  const TangentProbe p = small_probe();
  int previous = 0;
  for (double target : {0.2, 0.05, 0.01}) {
    const Choice c = select_tangent_samples(f, 0, target, p);
    ASSERT_FALSE(c.tried.empty());
    for (size_t i = 0; i + 1 < c.tried.size(); ++i) EXPECT_GT(c.tried[i].second, target);
    EXPECT_EQ(c.tried.back().first, c.value);
    if (c.value != p.candidates.back()) {
      EXPECT_LE(c.error, target);
    }
    EXPECT_GE(c.value, previous) << "target " << target;
    previous = c.value;
  }
}

TEST(LambdaLevelSelection, TighterTargetsNeedAtLeastAsManyLevels) {
  const Fabric f = preset("linen_plain");
  BakeSettings s;
  s.tangent_samples = {1, 1};
  s.xi_resolution = 16;
  s.wo_resolution = 12;
  s.wi_resolution = 32;
  s.lambda_max = 256.0;
  const Choice loose = select_lambda_levels(f, s, 0.5, 3);
  const Choice tight = select_lambda_levels(f, s, 1e-4, 3);
  EXPECT_LE(loose.value, tight.value);
  EXPECT_EQ(loose.value, 5);  // ×4 spacing misses T by far less than 50 %
  ASSERT_EQ(tight.tried.size(), 3u);
  // Finer spacing interpolates better: errors fall along 5, 9, 17 levels.
  EXPECT_GT(tight.tried[0].second, tight.tried[1].second);
  EXPECT_GT(tight.tried[1].second, tight.tried[2].second);
}

// The paper's per-cloth totals, split by need: a straight thread's samples are all one tilt,
// so it keeps 1 and the curved thread gets the rest. Against the probe's converged radiance the
// split must lose nothing on the straight thread and beat the even split at the same total.
TEST(PaperTangentSamples, StraightThreadKeepsOneAndTheTotalIsThePapers) {
  const std::map<std::string, int> paper_total = {{"linen_plain", 6},         {"polyester_satin_charmeuse", 16},
                                                  {"silk_crepe_de_chine", 10}, {"silk_shot", 10},
                                                  {"velvet", 8}};
  for (const auto& [name, total] : paper_total) {
    const Fabric f = preset(name);
    const auto n = paper_tangent_samples(f);
    EXPECT_EQ(n[0] + n[1], total) << name;
    for (int j = 0; j < 2; ++j) {
      const auto tilts = f.threads[j].curve.sample_tilts(8);
      const bool straight = std::all_of(tilts.begin(), tilts.end(), [&](double a) { return a == tilts.front(); });
      if (straight) {
        EXPECT_EQ(n[j], 1) << name << " thread " << j;
      }
    }
  }
  const Fabric satin = preset("polyester_satin_charmeuse");
  const TangentProbe p = small_probe();
  const auto split = paper_tangent_samples(satin);
  const double e_split = tangent_sample_error(satin, split, {16, 16}, p);
  const double e_even = tangent_sample_error(satin, {8, 8}, {16, 16}, p);
  std::printf("satin %d+%d: probe error %.4f; 8+8: %.4f\n", split[0], split[1], e_split, e_even);
  EXPECT_LT(e_split, 0.5 * e_even);
}
