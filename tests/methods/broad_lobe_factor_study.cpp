// Point study (bench label, no assertions): where iwasaki's error on broad SGs sits. Per (SG, view):
// iwasaki; T from the tables × the shading integral ∫G f_s cos θ_i by quadrature; and T by
// quadrature (Eq. 10) × the same, i.e. Eq. 9's factorisation alone; linen swatch, 4 views; prints
// CSV (docs/bench/low_sun/broad_lobe_limits/factorisation.csv).
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <vector>
#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "core/microcylinder.h"
#include "methods/iwasaki/iwasaki.h"
#include "reference/sg_quadrature.h"
#include "support/linen_swatch_study.h"
using namespace weft;
using test::at_elevation;
TEST(Study, Factor) {
  const test::LinenSwatchStudy study;
  const Fabric& linen = study.linen;
  const WeightingTables& tables = study.tables;
  const ClothBsdf &approx = study.approx, &exact = study.exact;
  const std::vector<dvec3>& views = study.views;
  const SurfaceFrame fr{};
  const int NP = 128, NA = 256;
  std::printf("lambda,elev,view,ref,iwasaki,tableT_exactshade,exactT_exactshade\n");
  for (double lambda : {0.5, 1.0, 2.0, 4.0, 16.0}) {
    for (double elev : {90.0, 60.0, 30.0, 10.0, 0.0}) {
      SphericalGaussian g{at_elevation(40, elev), lambda, dvec3(1)};
      for (size_t vi = 0; vi < views.size(); ++vi) {
        dvec3 wo = glm::normalize(views[vi]);
        SgLighting one{g};
        double ref = integrate_sg_lighting(exact, fr, wo, one).radiance.g;
        double iw = iwasaki_radiance(approx, tables, fr, wo, one).radiance.g;
        ClothBsdf::Point pt = approx.at(fr);
        const int ns = approx.total_samples();
        std::vector<double> gw(ns, 0.0), gs(ns, 0.0), w(ns);
        double g0 = 0.0;
        for (int a = 0; a < NP; ++a) {
          double th = (a + 0.5) / NP * M_PI / 2, dw0 = std::sin(th) * (M_PI / 2 / NP) * (2 * M_PI / NA);
          for (int b = 0; b < NA; ++b) {
            double ph = (b + 0.5) / NA * 2 * M_PI;
            dvec3 wi(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
            double G = g(wi).g * dw0;
            g0 += G;
            pt.weights(wi, wo, w);
            int s = 0;
            for (int j = 0; j < 2; ++j) {
              const ThreadParams& p = linen.threads[j];
              for (int k = 0; k < approx.sample_count(j); ++k, ++s) {
                ThreadFrame tf = thread_frame(fr, j, approx.tilt(j, k));
                FiberAngles in = fiber_angles(tf, wi), out = fiber_angles(tf, wo);
                gw[s] += G * w[s];
                gs[s] += G * scattering(p, in, out).g * std::cos(in.theta);
              }
            }
          }
        }
        dvec3 xl = g.axis;
        double tt = 0, et = 0; int s = 0;
        for (int j = 0; j < 2; ++j) {
          int n = approx.sample_count(j); double a1 = 0, a2 = 0;
          for (int k = 0; k < n; ++k, ++s) { a1 += tables.value(s, lambda, xl, wo) * gs[s]; a2 += gw[s] / g0 * gs[s]; }
          tt += a1 / n; et += a2 / n;
        }
        std::printf("%.2f,%.0f,%zu,%.4e,%+.1f,%+.1f,%+.1f\n", lambda, elev, vi, ref, 100*(iw/ref-1), 100*(tt/ref-1), 100*(et/ref-1));
        std::fflush(stdout);
      }
    }
  }
}
