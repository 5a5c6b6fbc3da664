// Point study (bench label, no assertions): broad SGs split into a centre + ring of sharper SGs
// (amplitudes by least squares on the sphere, ring angle searched) against the converged
// reference, linen swatch, 4 views; prints CSV (docs/bench/low_sun/broad_lobe_limits/split.csv).
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <vector>
#include <Eigen/Dense>
#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "methods/iwasaki/iwasaki.h"
#include "reference/sg_quadrature.h"
#include "support/linen_swatch_study.h"
using namespace weft;
using test::at_elevation;
namespace {
// centre + n ring lobes at angle beta, all sharpness ls; amplitudes by least squares on S^2
struct Split { double beta, ls, a0, a1, err; };
Split fit_split(double lambda, int n, double factor) {
  Split best{0,0,0,0,1e9};
  const double ls = lambda * factor;
  for (double beta = 0.05; beta < 1.6; beta += 0.01) {
    SphericalGaussian g{dvec3(0,0,1), lambda, dvec3(1)};
    std::vector<SphericalGaussian> b;
    b.push_back({dvec3(0,0,1), ls, dvec3(1)});
    for (int i = 0; i < n; ++i) { double p = 2*M_PI*i/n; b.push_back({dvec3(std::sin(beta)*std::cos(p), std::sin(beta)*std::sin(p), std::cos(beta)), ls, dvec3(1)}); }
    // two unknowns: a0 (centre), a1 (ring)
    Eigen::Matrix2d A = Eigen::Matrix2d::Zero(); Eigen::Vector2d r = Eigen::Vector2d::Zero();
    auto ip = [](const SphericalGaussian& x, const SphericalGaussian& y){ return inner_product(x,y).x; };
    double c00 = ip(b[0],b[0]), c01 = 0, c11 = 0, r0 = ip(g,b[0]), r1 = 0;
    for (int i = 1; i <= n; ++i) { c01 += ip(b[0],b[i]); r1 += ip(g,b[i]); for (int j = 1; j <= n; ++j) c11 += ip(b[i],b[j]); }
    A << c00, c01, c01, c11; r << r0, r1;
    Eigen::Vector2d a = A.ldlt().solve(r);
    double gg = ip(g,g);
    double e2 = gg - 2*a.dot(r) + a.dot(A*a);
    double err = std::sqrt(std::max(e2,0.0)/gg);
    if (err < best.err) best = {beta, ls, a(0), a(1), err};
  }
  return best;
}
SgLighting apply_split(const SphericalGaussian& g, int n, const Split& s) {
  dvec3 z = g.axis; dvec3 x = glm::normalize(glm::cross(std::abs(z.z) < 0.9 ? dvec3(0,0,1) : dvec3(1,0,0), z)); dvec3 y = glm::cross(z, x);
  SgLighting out; out.push_back({z, s.ls, g.amplitude * s.a0});
  for (int i = 0; i < n; ++i) { double p = 2*M_PI*i/n + 0.3; out.push_back({glm::normalize(std::cos(s.beta)*z + std::sin(s.beta)*(std::cos(p)*x + std::sin(p)*y)), s.ls, g.amplitude * s.a1}); }
  return out;
}
}
TEST(Study, Split) {
  const test::LinenSwatchStudy study;
  const WeightingTables& tables = study.tables;
  const ClothBsdf &approx = study.approx, &exact = study.exact;
  const std::vector<dvec3>& views = study.views;
  struct Cfg { int n; double f; };
  std::vector<Cfg> cfgs = {{4,3.0},{5,4.0},{6,4.0},{6,6.0},{8,8.0}};
  std::printf("lambda,elev,view,ref,direct");
  for (auto c : cfgs) std::printf(",split%d_x%.0f", c.n, c.f);
  std::printf("\n");
  for (double lambda : {0.5, 1.0, 2.0, 3.0, 4.0}) {
    std::vector<Split> sp; for (auto c : cfgs) { sp.push_back(fit_split(lambda, c.n, c.f)); std::fprintf(stderr, "lambda %.2f n %d x%.0f: beta %.2f a0 %.3f a1 %.3f err %.4f\n", lambda, c.n, c.f, sp.back().beta, sp.back().a0, sp.back().a1, sp.back().err); }
    for (double elev : {90.0, 60.0, 30.0, 10.0, 0.0, -20.0}) {
      SphericalGaussian g{at_elevation(40, elev), lambda, dvec3(1)};
      for (size_t vi = 0; vi < views.size(); ++vi) {
        dvec3 wo = glm::normalize(views[vi]);
        SgLighting one{g};
        double ref = integrate_sg_lighting(exact, SurfaceFrame{}, wo, one).radiance.g;
        double dir = iwasaki_radiance(approx, tables, SurfaceFrame{}, wo, one).radiance.g;
        std::printf("%.2f,%.0f,%zu,%.4e,%+.1f", lambda, elev, vi, ref, 100*(dir/ref-1));
        for (size_t c = 0; c < cfgs.size(); ++c) {
          SgLighting s = apply_split(g, cfgs[c].n, sp[c]);
          double v = iwasaki_radiance(approx, tables, SurfaceFrame{}, wo, s).radiance.g;
          std::printf(",%+.1f", 100*(v/ref-1));
        }
        std::printf("\n"); std::fflush(stdout);
      }
    }
  }
}
