// The close-up registered to the weave (capture/closeup_registration.h): simulated close-ups of
// a glossy satin (one dye, a long float's highlight beside a matte weft) and of a shot silk (two
// hues), each thread's mean read where the registered weave puts it, against the simulation's own
// truth: each thread's radiance along its float, integrated over the arc (an independent path,
// not the folded tile). And a close-up whose lattice the spectrum resolves but whose pixels show
// another weave is not registered.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "capture/closeup_registration.h"
#include "capture/closeup_shot.h"
#include "capture/closeup_simulation.h"
#include "core/fabric.h"
#include "core/weave_layout.h"

namespace {

const std::vector<weft::FitLight> kLights{{glm::normalize(glm::dvec3(0.3, 0.2, 1.0)), glm::dvec3(1.5, 1.4, 1.2)},
                                          {glm::normalize(glm::dvec3(-0.6, 0.1, 0.7)), glm::dvec3(0.8, 0.9, 1.0)},
                                          {glm::normalize(glm::dvec3(0.1, -0.8, 0.4)), glm::dvec3(0.5, 0.5, 0.6)}};

struct Shot {
  weft::SimulatedCloseup closeup;
  weft::ResponseModel response;
  weft::CloseupClusters clusters;
  double turn = 0;
};

Shot shoot(const weft::Fabric& fabric, double turn, std::uint64_t seed) {
  weft::SimulatedCamera camera;
  weft::CloseupSimulationOptions options;
  options.turn = turn;
  options.exposure_scale = 0.5;
  options.seed = seed;
  Shot s{weft::simulate_closeup(fabric, kLights, camera, options), camera.response, {}, turn};
  s.response.scale = camera.white_balance;
  s.clusters = weft::measure_closeup(s.closeup.photo, s.response, fabric.name);
  return s;
}

}  // namespace

TEST(CloseupRegistration, EachThreadsMeanWhereTheWeavePutsIt) {
  std::uint64_t seed = 11;
  for (const char* name : {"polyester_satin_charmeuse", "silk_shot"}) {
    const weft::Fabric fabric = weft::load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics");
    const Shot shot = shoot(fabric, 0.4 + seed, seed);
    ++seed;
    ASSERT_TRUE(shot.clusters.scale && shot.clusters.spectrum) << name;
    const weft::WeaveLayout layout(fabric);
    const weft::ThreadCounts counts = weft::weave_counts(*shot.clusters.spectrum, layout.rows(), layout.shift());
    ASSERT_TRUE(counts.resolved()) << name;
    const weft::CloseupRegistration r = weft::register_closeup(shot.closeup.photo, shot.response, *shot.clusters.scale, counts,
                                                               fabric, kLights, shot.turn);
    ASSERT_TRUE(r.registered) << name << ": " << r.why;
    // The weave's model explains nearly all of the tile at its phase, and little at most others.
    EXPECT_GT(r.explained, 0.9) << name;
    EXPECT_LT(r.explained_median, r.explained - 0.3) << name;
    EXPECT_GT(r.inner_bins[1], 100) << name;
    // Warp ÷ weft of the threads' means: the simulation's, to 3 % per channel.
    const glm::dvec3 ratio = r.thread_mean[0] / r.thread_mean[1];
    std::printf("%s: explained %.3f (median phase %.3f), ratio %.4f %.4f %.4f against %.4f %.4f %.4f, exposure %.4f\n", name,
                r.explained, r.explained_median, ratio.r, ratio.g, ratio.b, shot.closeup.warp_over_weft.r,
                shot.closeup.warp_over_weft.g, shot.closeup.warp_over_weft.b, r.exposure);
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(std::log(ratio[ch]), std::log(shot.closeup.warp_over_weft[ch]), 0.03) << name << " channel " << ch;
    // The exposure the model reads off the highlights is the simulation's (0.5, less whole stops), to a
    // quarter stop (the surface term sets it, and its lobe is a few degrees wide).
    const double stops = std::log2(0.5 / r.exposure);
    EXPECT_NEAR(stops, std::round(stops), 0.25) << name;
  }
}

TEST(CloseupRegistration, AnotherWeavesPixelsDoNotRegister) {
  // The satin's close-up read as a plain weave at the satin's own counts: the lattice is the
  // satin's, the plain weave's tile is not what the pixels show.
  const weft::Fabric satin = weft::load_fabric_preset("polyester_satin_charmeuse", WEFT_SOURCE_ASSETS "/fabrics");
  weft::Fabric plain = weft::load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  plain.weave = satin.weave;
  const Shot shot = shoot(satin, 1.1, 5);
  ASSERT_TRUE(shot.clusters.scale && shot.clusters.spectrum);
  const weft::WeaveLayout layout(satin);
  const weft::ThreadCounts counts = weft::weave_counts(*shot.clusters.spectrum, layout.rows(), layout.shift());
  ASSERT_TRUE(counts.resolved());
  const weft::CloseupRegistration right = weft::register_closeup(shot.closeup.photo, shot.response, *shot.clusters.scale, counts,
                                                                 satin, kLights, shot.turn);
  const weft::CloseupRegistration wrong = weft::register_closeup(shot.closeup.photo, shot.response, *shot.clusters.scale, counts,
                                                                 plain, kLights, shot.turn);
  std::printf("satin's tile: explained %.3f (median %.3f); as a plain weave: %.3f (median %.3f)\n", right.explained,
              right.explained_median, wrong.explained, wrong.explained_median);
  EXPECT_TRUE(right.registered) << right.why;
  EXPECT_FALSE(wrong.registered) << "explained " << wrong.explained << " against " << wrong.explained_median;
  EXPECT_LT(wrong.explained, right.explained - 0.2);
}
