// Point study (bench label, no assertions): SGs with the axis below the horizon, from broad ground
// lobes to a sharp sun 0.5–5° below, iwasaki against the converged reference, linen swatch, 4 views;
// prints CSV (docs/bench/low_sun/broad_lobe_limits/below_horizon.csv).
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <vector>
#include "bake/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "methods/iwasaki/iwasaki.h"
#include "reference/sg_quadrature.h"
using namespace weft;
static dvec3 at_elevation(double azimuth_deg, double elevation_deg) {
  const double a = glm::radians(azimuth_deg), e = glm::radians(elevation_deg);
  return dvec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
}
TEST(Study, HorizonSun) {
  Fabric linen = load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  BakeSettings st; st.tangent_samples = {3,3}; st.xi_resolution = st.wo_resolution = st.wi_resolution = 32; st.lambda_levels = 8;
  WeightingTables tables = bake_weighting_tables(linen, st);
  const ClothBsdf approx(linen, st.tangent_samples), exact(linen, 64);
  std::vector<dvec3> views = {dvec3(0,0,1), dvec3(0.3,0.2,0.93), dvec3(-0.6,0.3,0.74), dvec3(0.2,-0.9,0.3)};
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
