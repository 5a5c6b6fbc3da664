// Point study (bench label, no assertions): SGs with the axis below the horizon, from broad ground
// lobes to a sharp sun 0.5–5° below, iwasaki against the converged reference, linen swatch, 4 views;
// prints CSV (docs/bench/low_sun/broad_lobe_limits/below_horizon.csv).
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <vector>
#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "methods/iwasaki/iwasaki.h"
#include "reference/sg_quadrature.h"
#include "support/linen_swatch_study.h"
using namespace weft;
using test::at_elevation;
TEST(Study, HorizonSun) {
  const test::LinenSwatchStudy study;
  const WeightingTables& tables = study.tables;
  const ClothBsdf &approx = study.approx, &exact = study.exact;
  const std::vector<dvec3>& views = study.views;
  std::printf("lambda,elev,view,ref_over_full,err\n");
  std::vector<std::pair<double,double>> pts = {{0.28,-90},{0.5,-45},{1,-20},{2,-45},{2,-90},{4,-10},{16,-5},{16,-20},{30,-3},{30,-10}};
  for (double lambda : {100.0, 300.0, 1000.0})
    for (double elev : {1.0, 0.0, -0.5, -1.0, -2.0, -3.0, -5.0}) pts.push_back({lambda, elev});
  for (auto [lambda, elev] : pts) {
      SgLighting one{{at_elevation(40, elev), lambda, dvec3(1)}};
      SgLighting up{{at_elevation(40, 3), lambda, dvec3(1)}};
      for (size_t vi = 0; vi < views.size(); ++vi) {
        dvec3 wo = glm::normalize(views[vi]);
        double ref = integrate_sg_lighting(exact, SurfaceFrame{}, wo, one).radiance.g;
        double r3 = integrate_sg_lighting(exact, SurfaceFrame{}, wo, up).radiance.g;
        double iw = iwasaki_radiance(approx, tables, SurfaceFrame{}, wo, one).radiance.g;
        std::printf("%.2f,%.1f,%zu,%.3f,%+.1f\n", lambda, elev, vi, ref / r3, 100 * (iw / ref - 1));
        std::fflush(stdout);
      }
    }
}
