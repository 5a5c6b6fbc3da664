// The weave layer's factor filtered over a pixel's footprint (methods/weave/weave_ratio.h)
// against the point factor it averages: the same where the footprint is tiny, the yarn's share
// of it where it straddles a yarn's edge, and the same mean over the repeat (a box filter moves
// detail, not light).
#include <gtest/gtest.h>

#include <filesystem>

#include "core/fabric.h"
#include "methods/weave/weave_ratio.h"

using namespace weft;
using glm::dvec2;
using glm::dvec3;

namespace {
const std::filesystem::path kAssets = WEFT_SOURCE_ASSETS;

struct Swatch {
  Fabric fabric;
  ClothBsdf bsdf;
  WeaveLayout layout;
  SurfaceFrame frame = SurfaceFrame::from_normal_warp(dvec3(0, 0, 1), dvec3(1, 0, 0));
  dvec3 wo = glm::normalize(dvec3(0.3, -0.4, 0.85));
  std::vector<SphericalGaussian> sgs{{glm::normalize(dvec3(-0.45, 0.55, 0.70)), 30.0, {6.0, 6.0, 6.0}},
                                     {dvec3(0, 0, 1), 3.0, {0.8, 0.8, 0.8}}};
  WeaveTerms terms;
  explicit Swatch(const std::string& name)
      : fabric(load_fabric_preset(name, kAssets / "fabrics")), bsdf(fabric, 16), layout(fabric) {
    terms = weave_terms(bsdf, frame, wo, sgs);
  }
};
}  // namespace

TEST(WeaveRatioFiltered, TinyFootprintIsThePointFactor) {
  const Swatch s("linen_plain");
  for (double x = 0.013; x < 1.0; x += 0.07)
    for (double y = 0.021; y < 1.0; y += 0.09) {
      const dvec3 point = weave_ratio(s.bsdf, s.layout, s.frame, s.wo, {x, y}, s.terms, s.sgs);
      const dvec3 filtered = weave_ratio_filtered(s.bsdf, s.layout, s.frame, s.wo, {x, y}, {1e-7, 0}, {0, 1e-7}, s.terms, s.sgs);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(filtered[c], point[c], 1e-4 * (1.0 + point[c])) << x << ", " << y;
    }
}

TEST(WeaveRatioFiltered, AFootprintAcrossAYarnEdgeShowsTheYarnsShare) {
  const Swatch s("linen_plain");
  ASSERT_LT(s.layout.yarn_width(), 0.95);  // the preset has gaps between its yarns
  // Row 0's warp float: its yarn fills τ within ½ ± w/2 of the row; t = τ/rows at the edge.
  const double s_mid = 0.5 * s.layout.warp_share() * 0.8, edge_t = (0.5 + 0.5 * s.layout.yarn_width()) / s.layout.rows();
  const double h = 0.02;  // along t: two sub-samples inside the yarn, two in the gap
  const dvec3 inside = weave_ratio(s.bsdf, s.layout, s.frame, s.wo, {s_mid, edge_t - 0.1 * h}, s.terms, s.sgs);
  ASSERT_EQ(s.layout.at(s_mid, edge_t - 0.1 * h).thread, 0);
  ASSERT_GT(inside.g, 0.0);
  const dvec3 filtered = weave_ratio_filtered(s.bsdf, s.layout, s.frame, s.wo, {s_mid, edge_t}, {1e-7, 0}, {0, h}, s.terms, s.sgs);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(filtered[c], 0.5 * inside[c], 1e-3 * inside[c]);
}

TEST(WeaveRatioFiltered, KeepsTheRepeatsMean) {
  for (const std::string name : {"linen_plain", "polyester_satin_charmeuse"}) {
    const Swatch s(name);
    constexpr int kN = 96;
    // A footprint of about half a thread, turned: the layer draws up to one thread a pixel.
    const double scale = 2.0 / s.layout.rows();
    dvec3 point(0.0), filtered(0.0);
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j) {
        const dvec2 st((i + 0.5) / kN, (j + 0.5) / kN);
        point += weave_ratio(s.bsdf, s.layout, s.frame, s.wo, st, s.terms, s.sgs);
        filtered += weave_ratio_filtered(s.bsdf, s.layout, s.frame, s.wo, st, scale * dvec2(0.21, 0.05),
                                         scale * dvec2(-0.04, 0.17), s.terms, s.sgs);
      }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(filtered[c] / point[c], 1.0, 0.01) << name;
  }
}

// The layer fades by the pixel's footprint in threads, not in repeats: a five-end satin's repeat
// holds five yarns across, so at a fifth of a repeat a pixel holds a thread and shows the average
// (a repeat-scaled fade would still draw its floats there, 4 samples a pixel: moiré), while a plain
// weave (two yarns) at the same footprint still shows most of its weave.
TEST(WeaveDetail, FadesByThreadsAPixelNotRepeats) {
  const Swatch satin("polyester_satin_charmeuse"), plain("linen_plain");
  ASSERT_EQ(satin.layout.rows(), 5);
  ASSERT_EQ(plain.layout.rows(), 2);
  EXPECT_DOUBLE_EQ(weave_thread_footprint(satin.layout, 0.2), 1.0);
  const glm::dvec2 st{0.31, 0.47}, dx{0.2, 0.0}, dy{0.0, 0.2};
  const dvec3 gone = weave_factor(satin.bsdf, satin.layout, satin.frame, satin.wo, st, dx, dy, satin.sgs);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(gone[c], 1.0);
  EXPECT_DOUBLE_EQ(weave_detail(weave_thread_footprint(plain.layout, 0.2)), 1.0 - 0.2 * 0.2 * (3.0 - 2.0 * 0.2));
  // A quarter of a thread a pixel or finer: the whole filtered factor.
  EXPECT_DOUBLE_EQ(weave_detail(weave_thread_footprint(satin.layout, 0.05)), 1.0);
  const dvec3 whole = weave_factor(satin.bsdf, satin.layout, satin.frame, satin.wo, st, dx / 4.0, dy / 4.0, satin.sgs);
  const dvec3 filtered = weave_ratio_filtered(satin.bsdf, satin.layout, satin.frame, satin.wo, st, dx / 4.0, dy / 4.0,
                                              satin.terms, satin.sgs);
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(whole[c], filtered[c]);
}
