// The weave layer's per-float table (methods/weave/weave_float_table.h) against the layer's
// exact per-pixel shading (weave_ratio_filtered, every light at three arcs a float): over a
// repeat the table keeps the point-sampled mean (it moves detail, not light), and pixel by pixel
// it stays near the exact factor where a pixel holds half a thread, for a plain weave, a satin
// (its floats' highlight a tenth of a float) and the velvet (its pile's tilt jumps along a float).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <random>

#include "core/fabric.h"
#include "methods/weave/weave_float_table.h"
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
  SurfaceFrame frame = SurfaceFrame::from_normal_warp(glm::normalize(dvec3(0.1, -0.2, 1.0)), dvec3(1, 0, 0));
  dvec3 wo = glm::normalize(dvec3(0.3, -0.4, 0.85));
  std::vector<SphericalGaussian> sgs{{glm::normalize(dvec3(-0.45, 0.55, 0.70)), 30.0, {6.0, 6.0, 6.0}},
                                     {glm::normalize(dvec3(0.6, 0.3, 0.5)), 120.0, {9.0, 8.0, 7.0}},
                                     {dvec3(0, 0, 1), 3.0, {0.8, 0.8, 0.8}}};
  WeaveTerms terms;
  WeaveFloatTable table;
  explicit Swatch(const std::string& name)
      : fabric(load_fabric_preset(name, kAssets / "fabrics")), bsdf(fabric, kWeavePixelSamples), layout(fabric) {
    terms = weave_terms(bsdf, frame, wo, sgs);
    table = weave_float_table(bsdf, frame, wo, terms, sgs);
  }
};
}  // namespace

TEST(WeaveFloatTable, NodesAreTheFloatsResponseAtTheirArcs) {
  const Swatch s("polyester_satin_charmeuse");
  for (int j = 0; j < 2; ++j)
    for (int m = 0; m < kWeaveTableArcs; ++m) {
      const double arc = weave_table_arc(m);
      const dvec3 at = weave_table_at(s.table, j, arc);
      for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(at[c], s.table[size_t(j * kWeaveTableArcs + m)][c]);
      // Between two nodes: between their values.
      if (m + 1 < kWeaveTableArcs) {
        const dvec3 between = weave_table_at(s.table, j, arc + 0.5 / kWeaveTableArcs);
        const dvec3 next = s.table[size_t(j * kWeaveTableArcs + m + 1)];
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(between[c], 0.5 * (at[c] + next[c]), 1e-12 * (1.0 + at[c]));
      }
    }
  // Beyond the end nodes: the end nodes' values.
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(weave_table_at(s.table, 0, 0.0)[c], s.table[0][c]);
}

TEST(WeaveFloatTable, KeepsTheRepeatsMeanAndNearlyEachPixel) {
  for (const std::string name : {"linen_plain", "polyester_satin_charmeuse", "velvet"}) {
    const Swatch s(name);
    constexpr int kN = 64;
    // A footprint of about half a thread, turned.
    const double scale = 1.0 / s.layout.rows();
    const dvec2 dx = scale * dvec2(0.21, 0.05), dy = scale * dvec2(-0.04, 0.17);
    // The repeat's mean point-sampled finely (a highlight spans little of a float).
    constexpr int kPoints = 384;
    dvec3 point_mean(0.0);
    for (int i = 0; i < kPoints; ++i)
      for (int j = 0; j < kPoints; ++j)
        point_mean += weave_ratio(s.bsdf, s.layout, s.frame, s.wo, {(i + 0.5) / kPoints, (j + 0.5) / kPoints}, s.terms, s.sgs) /
                      double(kPoints * kPoints);
    dvec3 exact_mean(0.0), tabled_mean(0.0);
    double squared = 0.0, exact_squared = 0.0;
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j) {
        const dvec2 st((i + 0.5) / kN, (j + 0.5) / kN);
        const dvec3 exact = weave_ratio_filtered(s.bsdf, s.layout, s.frame, s.wo, st, dx, dy, s.terms, s.sgs);
        const dvec3 tabled = weave_ratio_tabled(s.layout, s.table, st, dx, dy, s.terms.fabric);
        exact_mean += exact / double(kN * kN);
        tabled_mean += tabled / double(kN * kN);
        squared += glm::dot(tabled - exact, tabled - exact);
        exact_squared += glm::dot(exact, exact);
      }
    const double rmse = std::sqrt(squared / exact_squared);
    std::cout << name << ": repeat mean over the point-sampled one: table " << tabled_mean.g / point_mean.g << ", exact "
              << exact_mean.g / point_mean.g << "; table's relative RMSE per pixel against the exact " << rmse << "\n";
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(tabled_mean[c] / point_mean[c], 1.0, 0.02) << name;
    EXPECT_LT(rmse, 0.10) << name;
  }
}
