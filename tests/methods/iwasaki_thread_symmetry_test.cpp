// Point study of asymmetric tangent-sample counts (linen, grid-12 tables as the search's quick
// runs bake them). Linen's two threads are identical, so the canonical model is symmetric under
// swapping them: N1+N2 samples with warp u shade exactly as N2+N1 with the warp turned by 90°
// (u → v; v = n × u → −u, and the symmetric tangent curve does not see the sign). The runtime
// (C++ twin; the GLSL is pinned to it with 2+3 samples by the parity tests) must keep that
// symmetry, with tables baked for 1+2 and for 2+1, up to the tables' interpolation. And with one
// sample a thread is a single flat cylinder (tilt 0): against the converged model it is far off
// wherever that thread's highlight faces the view, so which of 1+2 and 2+1 errs more depends on
// how the warp lies towards the lights and the camera, not on which thread is richer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "methods/iwasaki/iwasaki.h"
#include "reference/sg_quadrature.h"
#include "support/sky_direction.h"

using namespace weft;
using test::at_elevation;

namespace {


struct Tables {
  Fabric linen = load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  BakeSettings settings(std::array<int, 2> n) const {
    BakeSettings s;
    s.tangent_samples = n;
    s.xi_resolution = s.wo_resolution = s.wi_resolution = 12;
    return s;
  }
  WeightingTables t12 = bake_weighting_tables(linen, settings({1, 2}));
  WeightingTables t21 = bake_weighting_tables(linen, settings({2, 1}));
};
const Tables& tables() {
  static const Tables t;
  return t;
}

const SgLighting kLights = {{at_elevation(20, 50), 30.0, dvec3(1.0)},
                            {at_elevation(130, 25), 80.0, dvec3(0.7)},
                            {at_elevation(-100, 65), 4.0, dvec3(0.4)}};
const std::vector<dvec3> kViews = {at_elevation(0, 90),   at_elevation(200, 40), at_elevation(-60, 30),
                                   at_elevation(75, 55),  at_elevation(160, 20), at_elevation(-150, 60)};

double relative(const dvec3& a, const dvec3& b) { return glm::length(a - b) / glm::length(b); }

}  // namespace

TEST(IwasakiThreadSymmetry, SwappedCountsShadeAlikeWithTheWarpTurned) {
  const Tables& t = tables();
  const ClothBsdf b12(t.linen, {1, 2}), b21(t.linen, {2, 1});
  const SurfaceFrame along_x{}, along_y{dvec3(0, 0, 1), dvec3(0, 1, 0), dvec3(-1, 0, 0)};
  double worst = 0.0;
  for (const dvec3& wo : kViews) {
    const dvec3 a = iwasaki_radiance(b12, t.t12, along_x, wo, kLights).radiance;
    const dvec3 b = iwasaki_radiance(b21, t.t21, along_y, wo, kLights).radiance;
    // The model itself, to show the runtime keeps the symmetry the model has.
    const dvec3 ma = integrate_sg_lighting(b12, along_x, wo, kLights).radiance;
    const dvec3 mb = integrate_sg_lighting(b21, along_y, wo, kLights).radiance;
    std::printf("view (%5.2f %5.2f %5.2f): runtime 1+2 %.5f, 2+1 turned %.5f; model %.5f / %.5f\n", wo.x, wo.y, wo.z,
                a.g, b.g, ma.g, mb.g);
    EXPECT_LT(relative(ma, mb), 1e-3);
    worst = std::max(worst, relative(a, b));
  }
  std::printf("worst runtime asymmetry %.2f%%\n", 100 * worst);
  EXPECT_LT(worst, 0.03);
}

// The error of an under-sampled thread follows the warp: turning the warp by 90° trades the
// errors of 1+2 and 2+1 against the converged model (16+16 samples) at the same view.
TEST(IwasakiThreadSymmetry, WhichCountErrsMoreFollowsTheWarp) {
  const Fabric& linen = tables().linen;
  const ClothBsdf b12(linen, {1, 2}), b21(linen, {2, 1}), exact(linen, 16);
  const SurfaceFrame along_x{}, along_y{dvec3(0, 0, 1), dvec3(0, 1, 0), dvec3(-1, 0, 0)};
  int traded = 0;
  for (const dvec3& wo : kViews) {
    const dvec3 ref_x = integrate_sg_lighting(exact, along_x, wo, kLights).radiance;
    const dvec3 ref_y = integrate_sg_lighting(exact, along_y, wo, kLights).radiance;
    const double e12x = relative(integrate_sg_lighting(b12, along_x, wo, kLights).radiance, ref_x);
    const double e21x = relative(integrate_sg_lighting(b21, along_x, wo, kLights).radiance, ref_x);
    const double e12y = relative(integrate_sg_lighting(b12, along_y, wo, kLights).radiance, ref_y);
    const double e21y = relative(integrate_sg_lighting(b21, along_y, wo, kLights).radiance, ref_y);
    std::printf("view (%5.2f %5.2f %5.2f): warp x: 1+2 %.1f%%, 2+1 %.1f%%; warp y: 1+2 %.1f%%, 2+1 %.1f%%\n", wo.x,
                wo.y, wo.z, 100 * e12x, 100 * e21x, 100 * e12y, 100 * e21y);
    EXPECT_NEAR(e12x, e21y, 1e-3 + 1e-3 * e12x);
    EXPECT_NEAR(e21x, e12y, 1e-3 + 1e-3 * e21x);
    if ((e12x > e21x) != (e12y > e21y)) ++traded;
  }
  EXPECT_GT(traded, 0);
}
