// render/lighting: the 10-SG fit on procedural skies (low suns, a large sun, haze) keeps the
// diffuse irradiance within 3 % (fit_error.h's irradiance measure against the map itself).
#include <gtest/gtest.h>

#include "lighting/fit_error.h"
#include "lighting/procedural_sky.h"
#include "lighting/sg_fit.h"

using namespace weft;

namespace {
void expect_fit_within(const SkyParams& p, double bound) {
  const EnvMap map = procedural_sky(p);
  const SgLighting sgs = fit_sgs(map);
  ASSERT_EQ(sgs.size(), 10u);
  const double e = measure_fit_error(map, sgs).irradiance_rmse;
  EXPECT_LE(e, bound) << "elev " << p.elevation_deg << " size " << p.size_deg << " haze " << p.turbidity;
  // A sharp lobe sits on the sun (within a few of its diameters).
  bool on_sun = false;
  for (const auto& g : sgs) on_sun |= g.sharpness >= 100.0 && glm::dot(g.axis, sun_direction(p)) > std::cos(0.1);
  EXPECT_TRUE(on_sun) << "elev " << p.elevation_deg;
}
}  // namespace

TEST(SkyFit, IrradianceWithinThreePercentFromHorizonToHighSun) {
  for (double elev : {0.0, 5.0, 20.0, 60.0}) {
    SkyParams p;
    p.elevation_deg = elev;
    expect_fit_within(p, 0.03);
  }
}

TEST(SkyFit, IrradianceWithinThreePercentForLargeAndHazySuns) {
  SkyParams big;
  big.elevation_deg = 10.0, big.size_deg = 5.0;
  expect_fit_within(big, 0.03);
  SkyParams hazy;
  hazy.elevation_deg = 10.0, hazy.turbidity = 6.0;
  expect_fit_within(hazy, 0.03);
}
