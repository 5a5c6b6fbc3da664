// The close-up (capture/closeup_shot.h): two colour clusters read back from stripes of known
// linear colours (their means, shares and the gaps between them), one colour shaded along its
// floats told from two colours, unusable close-ups refused; and a simulated close-up of the resolved weave averages, by
// its clusters' means weighted by the coverages, to the fabric-level model (an independent path:
// ClothBsdf::Point::integrand, not the resolved samples).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "capture/capture_card.h"
#include "capture/capture_rejection.h"
#include "capture/closeup_shot.h"
#include "capture/closeup_simulation.h"
#include "core/fabric.h"
#include "core/weave_layout.h"

namespace {

// Linear values straight through: β = 1 about sRGB, no vignetting, unit scale.
const weft::ResponseModel kLinear{1.0, 0.0, glm::dvec3(1.0)};

// Vertical stripes, one period after another: (width in pixels, linear colour), a colour of
// −1 a gap (black).
weft::Photo stripes(const std::vector<std::pair<int, glm::dvec3>>& period, int width = 640, int height = 480) {
  const weft::CameraResponse curve = kLinear.curve();
  weft::Photo p{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 3)};
  int total = 0;
  for (const auto& [w, c] : period) total += w;
  for (int x = 0; x < width; ++x) {
    int at = x % total, k = 0;
    while (at >= period[k].first) at -= period[k++].first;
    const glm::dvec3 c = glm::max(period[k].second, glm::dvec3(0));
    for (int y = 0; y < height; ++y)
      for (int ch = 0; ch < 3; ++ch) p.rgb[(static_cast<size_t>(y) * width + x) * 3 + ch] = curve.encode(c[ch]);
  }
  return p;
}

// The cluster closer to `colour`.
int nearest(const weft::CloseupSplit& c, const glm::dvec3& colour) {
  return glm::length(c.mean[1] - colour) < glm::length(c.mean[0] - colour);
}

}  // namespace

TEST(CloseupShot, TwoThreadsAndTheirGapsReadBack) {
  const glm::dvec3 a(0.50, 0.20, 0.10), b(0.10, 0.30, 0.45), gap(-1);
  const weft::CloseupClusters both = weft::measure_closeup(stripes({{12, a}, {4, gap}, {6, b}, {4, gap}}), kLinear, "stripes");
  EXPECT_NEAR(both.gap_share, 8.0 / 26.0, 0.02);
  ASSERT_EQ(both.splits.size(), 2u);
  for (const weft::CloseupSplit& c : both.splits) {
  const int ia = nearest(c, a), ib = 1 - ia;
  ASSERT_NE(ia, ib);
  for (int ch = 0; ch < 3; ++ch) {
    // 8-bit codes: within half a code's step of the sRGB curve at these levels.
    EXPECT_NEAR(c.mean[ia][ch], a[ch], 0.01 * a[ch] + 0.002);
    EXPECT_NEAR(c.mean[ib][ch], b[ch], 0.01 * b[ch] + 0.002);
  }
  // Inner pixels only: each stripe loses its two edge columns (10 of 12, 4 of 6).
  EXPECT_NEAR(c.share[ia], 10.0 / 14.0, 0.02);  // the frame ends mid-period
  EXPECT_LT(c.valley, 0.05);  // nothing between the two colours
  EXPECT_TRUE(c.separated());
  }
}

TEST(CloseupShot, ThreadsOfOneHueSeparateByLightness) {
  const glm::dvec3 light(0.50, 0.25, 0.125), dark(0.08, 0.04, 0.02);
  const weft::CloseupClusters both = weft::measure_closeup(stripes({{9, light}, {9, dark}}), kLinear, "stripes");
  EXPECT_TRUE(both.separated());
  const weft::CloseupSplit& c = both.splits[0];  // with lightness
  EXPECT_TRUE(c.separated());
  EXPECT_NEAR(c.mean[nearest(c, light)].r, light.r, 0.01);
  EXPECT_NEAR(c.mean[nearest(c, dark)].r, dark.r, 0.003);
}

TEST(CloseupShot, OneColourShadedAlongItsFloatsDoesNotSeparate) {
  // One thread colour whose brightness runs 0.2 → 1 along each 24-pixel float, as a float's tilt
  // sweeps its highlight: the k-means still cuts it in two, but nothing lies between two colours.
  std::vector<std::pair<int, glm::dvec3>> period;
  for (int k = 0; k < 24; ++k) period.push_back({1, (0.2 + 0.8 * k / 23.0) * glm::dvec3(0.45, 0.30, 0.20)});
  period.push_back({3, glm::dvec3(-1)});
  const weft::CloseupClusters c = weft::measure_closeup(stripes(period), kLinear, "shaded");
  for (const weft::CloseupSplit& s : c.splits) EXPECT_GT(s.valley, weft::CloseupSplit::kSeparatedValley);
  EXPECT_FALSE(c.separated());
}

TEST(CloseupShot, OneFlatColourIsOneColour) {
  // Nothing to split, or a few stray pixels of another colour: one colour, not two threads.
  EXPECT_FALSE(weft::measure_closeup(stripes({{10, glm::dvec3(0.3)}}), kLinear, "flat").separated());
  EXPECT_FALSE(weft::measure_closeup(stripes({{300, glm::dvec3(0.3)}, {3, glm::dvec3(0.5, 0.1, 0.1)}}), kLinear, "speck").separated());
}

TEST(CloseupShot, UnusableCloseupsAreRefused) {
  // Blown out.
  EXPECT_THROW(weft::measure_closeup(stripes({{10, glm::dvec3(1.0)}, {10, glm::dvec3(0.2, 0.3, 0.4)}}), kLinear, "white"),
               weft::CaptureRejection);
  // Black: no thread pixels.
  EXPECT_THROW(weft::measure_closeup(stripes({{10, glm::dvec3(0.0)}}), kLinear, "black"), weft::CaptureRejection);
  // Threads a pixel wide: no inner pixels.
  EXPECT_THROW(weft::measure_closeup(stripes({{1, glm::dvec3(0.5, 0.2, 0.1)}, {1, glm::dvec3(0.1, 0.2, 0.5)}}), kLinear, "fine"),
               weft::CaptureRejection);
}

TEST(CloseupShot, SimulatedResolvedWeaveAveragesToTheFabricLevel) {
  const weft::Fabric fabric = weft::load_fabric_preset("silk_shot", WEFT_SOURCE_ASSETS "/fabrics");
  const std::vector<weft::FitLight> lights{{glm::normalize(glm::dvec3(0.3, 0.2, 1.0)), glm::dvec3(1.5, 1.4, 1.2)},
                                           {glm::normalize(glm::dvec3(-0.6, 0.1, 0.7)), glm::dvec3(0.8, 0.9, 1.0)},
                                           {glm::normalize(glm::dvec3(0.1, -0.8, 0.4)), glm::dvec3(0.5, 0.5, 0.6)}};
  weft::SimulatedCamera camera;
  camera.shot_noise = camera.read_noise = 0;
  weft::CloseupSimulationOptions options;
  options.turn = 0.7;
  options.exposure_scale = 0.5;
  const weft::SimulatedCloseup shot = weft::simulate_closeup(fabric, lights, camera, options);
  const weft::Photo& photo = shot.photo;
  weft::ResponseModel response = camera.response;  // the curve and vignetting; the white balance undone
  response.scale = camera.white_balance;
  const weft::CloseupClusters clusters = weft::measure_closeup(photo, response, "closeup");
  ASSERT_TRUE(clusters.separated());
  const weft::CloseupSplit& c = clusters.splits[1];  // on colour: green and red
  // The warp is green, the weft red (the preset's colours).
  const int warp = c.mean[1].g > c.mean[0].g;
  const glm::dvec3 resolved = fabric.threads[0].coverage * c.mean[warp] + fabric.threads[1].coverage * c.mean[1 - warp];
  const glm::dvec3 level = weft::swatch_radiance(fabric, options.turn, glm::dvec3(0, 0, 1), lights, 32);
  // Chromaticity (the exposure is the simulation's own): within 3 % per channel.
  const glm::dvec3 a = resolved / (resolved.r + resolved.g + resolved.b), b = level / (level.r + level.g + level.b);
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(a[ch], b[ch], 0.03 * b[ch] + 0.002) << "channel " << ch;
  // The clusters' ratio is the threads' (each thread's mean along its float, from the simulation).
  const glm::dvec3 ratio = c.mean[warp] / c.mean[1 - warp];
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(std::log(ratio[ch]), std::log(shot.warp_over_weft[ch]), 0.03) << "channel " << ch;
  // The warp covers 86 % of the weave; the weft's floats are the rest.
  EXPECT_NEAR(c.share[warp], fabric.threads[0].coverage / (fabric.threads[0].coverage + fabric.threads[1].coverage), 0.08);
}

// The swatch's level straight above, read over the scale tag's white border (its exposure and
// white balance the close-up's own, not the photos'): against the model's mean radiance of the
// swatch straight above (core's swatch_radiance, the photos' own simulation) over a white
// diffuser's under the same lamps, with the camera's noise, its JPEG and a 1.7× exposure.
TEST(CloseupShot, LevelOverTheTagsPaperIsTheSwatchStraightAbove) {
  const std::vector<weft::FitLight> lights{{glm::normalize(glm::dvec3(0.3, 0.2, 1.0)), glm::dvec3(1.5, 1.4, 1.2)},
                                           {glm::normalize(glm::dvec3(-0.6, 0.1, 0.7)), glm::dvec3(0.8, 0.9, 1.0)},
                                           {glm::normalize(glm::dvec3(0.1, -0.8, 0.4)), glm::dvec3(0.5, 0.5, 0.6)}};
  glm::dvec3 white(0);
  for (const weft::FitLight& l : lights) white += l.power * std::max(l.direction.z, 0.0) / std::numbers::pi;
  const weft::SimulatedCamera camera;
  weft::ResponseModel response = camera.response;
  response.scale = glm::dvec3(1.7);  // any photo's scale: the paper's cancels it
  int k = 0;
  for (const char* name : {"silk_shot", "linen_plain", "polyester_satin_charmeuse_back"}) {
    const weft::Fabric fabric = weft::load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics");
    weft::CloseupSimulationOptions options;
    options.turn = 0.4 + 0.9 * k;
    options.seed = 11 + k++;
    const weft::CloseupClusters c = weft::measure_closeup(weft::simulate_closeup(fabric, lights, camera, options).photo, response, name);
    ASSERT_TRUE(c.level.has_value()) << name;
    const glm::dvec3 expected = weft::swatch_radiance(fabric, options.turn, glm::dvec3(0, 0, 1), lights, 32) / white;
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(std::log((*c.level)[ch]), std::log(expected[ch]), 0.03) << name << " channel " << ch;
  }
  // No tag, no level.
  weft::CloseupSimulationOptions bare;
  bare.scale_tag = false;
  const weft::Fabric linen = weft::load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  EXPECT_FALSE(weft::measure_closeup(weft::simulate_closeup(linen, lights, camera, bare).photo, response, "bare").level);
}

// Ends and picks per cm (capture/thread_counts.h) from simulated close-ups of the opaque presets'
// weaves (plain, twill-like, satin, its back; velvet's dark pile under these two lamps leaves
// too few thread pixels, and is checked end to end by `weft capture`) at counts drawn around
// their own, the scale tag in a random corner: against the counts the simulation drew the weave
// with, where the lattice is resolved (4 of the 5 at least).
TEST(CloseupThreads, CountsFromTheSpectrumAreTheWeaves) {
  const std::vector<weft::FitLight> lights{{glm::normalize(glm::dvec3(0.3, 0.2, 1.0)), glm::dvec3(1.5, 1.4, 1.2)},
                                           {glm::normalize(glm::dvec3(-0.6, 0.1, 0.7)), glm::dvec3(0.8, 0.9, 1.0)}};
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> scale(0.7, 1.3);
  std::uint64_t seed = 1;
  int checked = 0;
  for (const char* name : {"linen_plain", "polyester_satin_charmeuse", "polyester_satin_charmeuse_back",
                                  "silk_crepe_de_chine", "silk_shot"}) {
    weft::Fabric fabric = weft::load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics");
    fabric.weave.ends_per_cm = std::round(fabric.weave.ends_per_cm * scale(rng));
    fabric.weave.picks_per_cm = std::round(fabric.weave.picks_per_cm * scale(rng));
    weft::SimulatedCamera camera;
    weft::CloseupSimulationOptions options;
    options.turn = 2.0 * seed;
    options.exposure_scale = 0.5;
    options.seed = ++seed;
    const weft::SimulatedCloseup shot = weft::simulate_closeup(fabric, lights, camera, options);
    weft::ResponseModel response = camera.response;
    response.scale = camera.white_balance;
    const weft::CloseupClusters c = weft::measure_closeup(shot.photo, response, name);
    ASSERT_TRUE(c.scale) << name << ": the scale tag was not found";
    EXPECT_NEAR(c.scale->px_per_mm, options.width / options.field_mm, 0.01 * options.width / options.field_mm) << name;
    ASSERT_TRUE(c.spectrum) << name;
    const weft::WeaveLayout layout(fabric);
    const weft::ThreadCounts t = weft::weave_counts(*c.spectrum, layout.rows(), layout.shift());
    // Not every weave's lattice is resolved (a lattice that leaves a fifth of the lines' weight off
    // once fitted is not taken); one that is must be right.
    if (!t.resolved()) continue;
    ++checked;
    EXPECT_NEAR(t.angle, 0.0, 0.02) << name;  // the simulation lays the tag along the warp
    EXPECT_NEAR(t.ends_per_cm, fabric.weave.ends_per_cm, 0.02 * fabric.weave.ends_per_cm) << name;
    EXPECT_NEAR(t.picks_per_cm, fabric.weave.picks_per_cm, 0.02 * fabric.weave.picks_per_cm) << name;
  }
  EXPECT_GE(checked, 4);
}

// Without the tag there are no millimetres: no counts, and the clusters as before. A frame of
// paper with the tag on it (no yarns) has a scale but resolves no yarns.
TEST(CloseupThreads, NoTagNoCountsAndNoYarnsNoCounts) {
  const weft::Fabric fabric = weft::load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  const std::vector<weft::FitLight> lights{{glm::dvec3(0, 0, 1), glm::dvec3(1.0)}};
  weft::SimulatedCamera camera;
  weft::ResponseModel response = camera.response;
  response.scale = camera.white_balance;
  weft::CloseupSimulationOptions options;
  options.exposure_scale = 0.5;
  options.scale_tag = false;
  const weft::CloseupClusters bare = weft::measure_closeup(weft::simulate_closeup(fabric, lights, camera, options).photo, response, "bare");
  EXPECT_FALSE(bare.scale);
  EXPECT_FALSE(bare.spectrum);
  EXPECT_EQ(bare.splits.size(), 2u);

  // A flat grey frame with noise and the tag drawn on it at 150 px/mm, its +x at 20° in the
  // image: the scale and the warp's direction, and no yarns.
  const int w = 1200, h = 900;
  const double px_per_mm = 150, theta = glm::radians(20.0);
  const glm::dvec2 a(std::cos(theta), std::sin(theta)), b(-a.y, a.x), centre(300, 300);
  const weft::CameraResponse curve = kLinear.curve();
  std::mt19937_64 noise(5);
  std::normal_distribution<double> unit(0.0, 0.004);
  weft::Photo flat{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 3)};
  const weft::CardTag& tag = weft::capture_card().closeup_tag;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::dvec2 d = (glm::dvec2(x + 0.5, y + 0.5) - centre) / px_per_mm;
      const double r = weft::tag_reflectance(tag.id, tag.size, {glm::dot(d, a), glm::dot(d, b)});
      const double v = r >= 0 ? 0.8 * r : 0.4 + unit(noise);
      for (int ch = 0; ch < 3; ++ch) flat.rgb[(static_cast<size_t>(y) * w + x) * 3 + ch] = curve.encode(v);
    }
  const weft::CloseupClusters paper = weft::measure_closeup(flat, kLinear, "paper");
  ASSERT_TRUE(paper.scale);
  EXPECT_NEAR(paper.scale->px_per_mm, px_per_mm, 1.0);
  EXPECT_GT(glm::dot(paper.scale->warp, a), 0.999);
  EXPECT_NEAR(glm::length(paper.scale->centre - centre), 0.0, 1.0);
  ASSERT_TRUE(paper.spectrum);
  for (const auto& [rows, shift] : {std::pair{2, 1}, std::pair{4, 1}, std::pair{5, 2}}) {
    const weft::ThreadCounts t = weft::weave_counts(*paper.spectrum, rows, shift);
    EXPECT_FALSE(t.resolved()) << rows << " rows: score " << t.score;
  }
}
