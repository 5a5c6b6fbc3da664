// The weave layer's factor filtered over a pixel's footprint (methods/weave/weave_ratio.h)
// against the point factor it averages: the same where the footprint is tiny, the yarn's share
// of it where it straddles a yarn's edge, and the same mean over the repeat (a box filter moves
// detail, not light).
#include <gtest/gtest.h>

#include <iostream>

#include <cmath>
#include <filesystem>
#include <numbers>

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
    constexpr int kN = 96, kPoints = 4 * kN;  // the point samples finer: a highlight spans little of a float
    // A footprint of about half a thread, turned: the layer draws up to one thread a pixel.
    const double scale = 2.0 / s.layout.rows();
    dvec3 point(0.0), filtered(0.0);
    for (int i = 0; i < kPoints; ++i)
      for (int j = 0; j < kPoints; ++j)
        point += weave_ratio(s.bsdf, s.layout, s.frame, s.wo, {(i + 0.5) / kPoints, (j + 0.5) / kPoints}, s.terms, s.sgs) /
                 double(kPoints * kPoints);
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j) {
        const dvec2 st((i + 0.5) / kN, (j + 0.5) / kN);
        filtered += weave_ratio_filtered(s.bsdf, s.layout, s.frame, s.wo, st, scale * dvec2(0.21, 0.05),
                                         scale * dvec2(-0.04, 0.17), s.terms, s.sgs) /
                    double(kN * kN);
      }
    std::cout << name << ": filtered over point-sampled repeat mean " << filtered.g / point.g << "\n";
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
  // A footprint of kWeaveCoarseFootprint threads: the fabric level, exactly.
  const glm::dvec2 st{0.31, 0.47};
  const double coarse = kWeaveCoarseFootprint / satin.layout.rows();
  const dvec3 gone = weave_factor(satin.bsdf, satin.layout, satin.frame, satin.wo, st, {coarse, 0.0}, {0.0, coarse}, satin.sgs);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(gone[c], 1.0);
  // Halfway between the two footprints in threads the plain weave is half faded (smoothstep); the
  // same footprint in repeats holds 2.5 times the threads of the five-end satin, which is gone.
  const double mid = 0.5 * (kWeaveFineFootprint + kWeaveCoarseFootprint) / plain.layout.rows();
  EXPECT_DOUBLE_EQ(weave_detail(weave_thread_footprint(plain.layout, mid)), 0.5);
  EXPECT_DOUBLE_EQ(weave_detail(weave_thread_footprint(satin.layout, mid)), 0.0);
  // kWeaveFineFootprint threads a pixel or finer: the whole filtered factor.
  const double fine = kWeaveFineFootprint / satin.layout.rows();
  EXPECT_DOUBLE_EQ(weave_detail(weave_thread_footprint(satin.layout, fine)), 1.0);
  const dvec3 whole = weave_factor(satin.bsdf, satin.layout, satin.frame, satin.wo, st, {fine, 0.0}, {0.0, fine}, satin.sgs);
  const dvec3 filtered = weave_ratio_filtered(satin.bsdf, satin.layout, satin.frame, satin.wo, st, {fine, 0.0}, {0.0, fine},
                                              satin.terms, satin.sgs);
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(whole[c], filtered[c]);
}

// An SG across the surface's horizon as the layer's point light (horizon_light): the share of its
// power above the horizon and that part's mean elevation, against the SG integrated on a fine
// polar grid about its axis.
TEST(HorizonLight, IsTheSgsPartAboveTheHorizonAtItsMeanElevation) {
  const dvec3 n(0, 0, 1);
  for (double lambda : {30.0, 300.0, 1000.0}) {
    const double sigma = 1.0 / std::sqrt(lambda);
    for (double e0_sigmas : {-1.5, -0.5, 0.0, 0.5, 1.0, 2.0}) {
      const double e0 = e0_sigmas * sigma;
      const SphericalGaussian g{dvec3(std::cos(e0), 0.0, std::sin(e0)), lambda, dvec3(1.0)};
      // ∫ G over the sphere and over ω·n > 0, and ∫ G·elevation above, on a polar grid about ξ.
      const dvec3 e1 = glm::normalize(glm::cross(g.axis, dvec3(0, 1, 0))), e2 = glm::cross(g.axis, e1);
      constexpr int kR = 600, kA = 720;
      const double rho_max = 8.0 * sigma;
      double all = 0.0, above = 0.0, elevation = 0.0;
      for (int i = 0; i < kR; ++i) {
        const double rho = (i + 0.5) / kR * rho_max;
        const double w = std::exp(lambda * (std::cos(rho) - 1.0)) * std::sin(rho);
        for (int a = 0; a < kA; ++a) {
          const double psi = (a + 0.5) / kA * 2.0 * std::numbers::pi;
          const dvec3 d = std::cos(rho) * g.axis + std::sin(rho) * (std::cos(psi) * e1 + std::sin(psi) * e2);
          all += w;
          if (glm::dot(d, n) > 0.0) {
            above += w;
            elevation += w * std::asin(glm::dot(d, n));
          }
        }
      }
      const HorizonLight light = horizon_light(g, n);
      EXPECT_NEAR(light.share, above / all, 0.01) << "λ " << lambda << ", axis " << e0_sigmas << "σ above the horizon";
      EXPECT_NEAR(std::asin(light.axis.z), elevation / above, 0.05 * sigma) << "λ " << lambda << ", axis " << e0_sigmas << "σ";
      EXPECT_NEAR(light.axis.y, 0.0, 1e-12);  // it rises in the plane of ξ and n
    }
  }
  // Far above the horizon: the SG's own axis with all its power.
  const SphericalGaussian high{glm::normalize(dvec3(0.3, -0.2, 0.9)), 300.0, dvec3(1.0)};
  const HorizonLight light = horizon_light(high, n);
  EXPECT_DOUBLE_EQ(light.share, 1.0);
  EXPECT_NEAR(glm::length(light.axis - high.axis), 0.0, 1e-12);
  // Far below: nothing.
  EXPECT_LT(horizon_light(SphericalGaussian{dvec3(0, 0, -1), 300.0, dvec3(1.0)}, n).share, 1e-12);
}
