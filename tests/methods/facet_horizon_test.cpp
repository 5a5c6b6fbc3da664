// facet_horizon_factor (methods/iwasaki/iwasaki.h): the share of a sharp SG above both the shading
// plane and a facet's plane a few degrees from it, over its share above the shading plane, against
// that ratio by quadrature (the SG-warped grid at 512 × 1024 cells, each cell kept or not by both
// planes). The closed form is min(1, H_facet/H_shading): exact where the planes coincide or only
// one of them cuts the lobe; where both cut it near their crossing it is an approximation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/spherical_gaussian.h"
#include "methods/iwasaki/iwasaki.h"
#include "support/facet_share.h"
#include "support/sky_direction.h"

using namespace weft;
using test::at_elevation;

namespace {

// Measured worst 0.040: where the planes cross inside the lobe (azimuth 0°, the lobe 1° below the
// shading horizon: min() keeps the part the facet cuts off on one side, 1–4 %); where one plane
// cuts the lobe, within 0.001.
constexpr double kFacetBound = 0.06;

}  // namespace

TEST(FacetHorizon, ShareAboveBothPlanesMatchesQuadrature) {
  const dvec3 ns(0, 0, 1);
  double worst = 0.0;
  int cut = 0;
  for (double tilt : {2.0, 5.0}) {
    const double t = glm::radians(tilt);
    const dvec3 ng(0.0, std::sin(t), std::cos(t));  // tilted towards +y: it rises above the horizon at azimuth −90°
    for (double lambda : {100.0, 300.0, 1000.0})
      for (double azimuth : {-90.0, 0.0, 90.0, 150.0})
        for (double elevation : {-1.0, 0.0, 1.0, 3.0, 6.0, 12.0, 30.0}) {
          const SphericalGaussian g{at_elevation(azimuth, elevation), lambda, dvec3(1.0)};
          const double exact = test::facet_share_by_quadrature(g, ns, ng);
          const double got = facet_horizon_factor(g, ns, ng);
          EXPECT_LE(got, 1.0);
          if (exact < 0.99) ++cut;
          const double e = std::abs(got - exact);
          if (e > worst)
            std::printf("tilt %.0f°, λ %.0f, azimuth %.0f°, elevation %.0f°: factor %.4f, quadrature %.4f\n", tilt, lambda,
                        azimuth, elevation, got, exact);
          worst = std::max(worst, e);
        }
  }
  std::printf("worst |factor − quadrature| %.4f over the cases; %d cases cut by more than 1 %%\n", worst, cut);
  EXPECT_GT(cut, 10);
  EXPECT_LT(worst, kFacetBound);
  // Coinciding planes and a zero facet normal leave the SG whole.
  const SphericalGaussian low{at_elevation(30, 1), 500.0, dvec3(1.0)};
  EXPECT_EQ(facet_horizon_factor(low, ns, ns), 1.0);
  EXPECT_EQ(facet_horizon_factor(low, ns, dvec3(0.0)), 1.0);
}
