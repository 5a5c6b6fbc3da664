// Point study (bench label, no assertions): a sharp SG a few degrees above the horizon (the bundled
// studio's λ ≈ 300 lobes, 1–23° up, which carry the pillow's error under that map: docs/research/iwasaki.md,
// docs/bench/low_sun/error_budget/quadrature_study/), iwasaki against the converged reference on the
// linen swatch, lights around the azimuth and views from the normal to grazing; prints CSV.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "methods/iwasaki/iwasaki.h"
#include "reference/sg_quadrature.h"
#include "support/linen_swatch_study.h"

using namespace weft;

namespace {
dvec3 direction(double azimuth_deg, double elevation_deg) {
  const double a = glm::radians(azimuth_deg), e = glm::radians(elevation_deg);
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}
}  // namespace

TEST(Study, GrazingSharpLobe) {
  const test::LinenSwatchStudy study;
  std::printf("lambda,light_azimuth,light_elevation,view_azimuth,view_elevation,reference,err_percent,model_3_3_err_percent\n");
  for (double lambda : {300.0, 1000.0})
    for (double elev : {1.0, 2.0, 4.0, 6.0, 10.0, 20.0})
      for (double az : {0.0, 45.0, 90.0})
        for (double view_az : {0.0, 90.0, 180.0, 225.0})
          for (double view_el : {10.0, 30.0, 60.0, 89.0}) {
            SgLighting one{{direction(az, elev), lambda, dvec3(1)}};
            const dvec3 wo = direction(view_az, view_el);
            const double ref = integrate_sg_lighting(study.exact, SurfaceFrame{}, wo, one).radiance.g;
            const double iw = iwasaki_radiance(study.approx, study.tables, SurfaceFrame{}, wo, one).radiance.g;
            // The model itself at the runtime's 3+3 tangent samples: what the samples cost, apart from iwasaki.
            const double coarse = integrate_sg_lighting(study.approx, SurfaceFrame{}, wo, one).radiance.g;
            std::printf("%.0f,%.0f,%.0f,%.0f,%.0f,%.4g,%+.1f,%+.1f\n", lambda, az, elev, view_az, view_el, ref,
                        ref > 0 ? 100 * (iw / ref - 1) : 0.0, ref > 0 ? 100 * (coarse / ref - 1) : 0.0);
          }
}

// The pillow's silhouette under the bundled studio (grazing_pillow_study): a λ = 311 SG 26° up and
// the view opposite it, a degree or two over the horizon. Sweeps the view's elevation through the
// last few degrees, where the converged model changes several-fold.
TEST(Study, GrazingView) {
  const test::LinenSwatchStudy study;
  std::printf("light_azimuth,view_elevation,reference,model_3_3,iwasaki\n");
  for (double az : {0.0, 45.0, 90.0})
    for (double view_el : {0.1, 0.2, 0.4, 0.7, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 10.0}) {
      SgLighting one{{direction(az, 26.0), 311.0, dvec3(1)}};
      const dvec3 wo = direction(az + 180.0, view_el);
      const double ref = integrate_sg_lighting(study.exact, SurfaceFrame{}, wo, one).radiance.g;
      const double coarse = integrate_sg_lighting(study.approx, SurfaceFrame{}, wo, one).radiance.g;
      const double iw = iwasaki_radiance(study.approx, study.tables, SurfaceFrame{}, wo, one).radiance.g;
      std::printf("%.0f,%.1f,%.4g,%.4g,%.4g\n", az, view_el, ref, coarse, iw);
    }
}
