// render/lighting: the 10-SG fit on procedural skies keeps the diffuse irradiance within 3 %
// (fit_error.h's measure against the map itself) on every sky of `weft bench --sweep sky`, both
// as `weft fit` runs it and as the light probe updates (a 128×64 map, its options, warm-started);
// and a small sun is one lobe, at the sun's direction with the disc's power.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "probe/light_probe_pipeline.h"
#include "lighting/fit_error.h"
#include "lighting/procedural_sky.h"
#include "lighting/sg_fit.h"

using namespace weft;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

// The skies of `weft bench --sweep sky` (render/bench/sky_sweep.cpp), on 512×256 maps.
std::vector<SkyParams> sweep_skies() {
  std::vector<SkyParams> out;
  for (double elev : {0.0, 5.0, 10.0, 20.0, 35.0, 60.0}) {
    SkyParams p;
    p.elevation_deg = elev;
    out.push_back(p);
  }
  for (double size : {2.0, 5.0}) {
    SkyParams p;
    p.elevation_deg = 10.0, p.size_deg = size;
    out.push_back(p);
  }
  SkyParams hazy;
  hazy.elevation_deg = 10.0, hazy.turbidity = 6.0;
  out.push_back(hazy);
  for (auto& p : out) p.width = 512;
  return out;
}

std::string label(const SkyParams& p) {
  return "elev " + std::to_string(p.elevation_deg) + " size " + std::to_string(p.size_deg) + " haze " +
         std::to_string(p.turbidity);
}

double power_of(const SphericalGaussian& g) {
  return (g.amplitude.r + g.amplitude.g + g.amplitude.b) / 3.0 * sg_sphere_integral(g.sharpness);
}
}  // namespace

TEST(SkyFit, EverySweepSkyWithinThreePercentWithLobesTheTablesCover) {
  for (const SkyParams& p : sweep_skies()) {
    const EnvMap map = procedural_sky(p);
    const SgLighting sgs = fit_sgs(map);
    ASSERT_EQ(sgs.size(), 10u);
    EXPECT_LE(measure_fit_error(map, sgs).irradiance_rmse, 0.03) << label(p);
    // Lobes within what the shading tables cover (λ 1/16..1024).
    for (const auto& g : sgs) {
      EXPECT_GE(g.sharpness, 1.0 / 16.0) << label(p);
      EXPECT_LE(g.sharpness, 1024.0) << label(p);
    }
  }
}

TEST(SkyFit, ProbeUpdatesOfEverySweepSkyWithinThreePercent) {
  const SgFitOptions probe = LightProbeConfig{}.fit;
  for (const SkyParams& p : sweep_skies()) {
    const EnvMap map = procedural_sky(p);
    const EnvMap small = resample(map, LightProbeConfig{}.map_width, LightProbeConfig{}.map_width / 2);
    SgLighting sgs = fit_sgs(small, probe);
    EXPECT_LE(measure_fit_error(map, sgs).irradiance_rmse, 0.03) << "cold, " << label(p);
    for (int update = 0; update < 2; ++update) sgs = fit_sgs(small, probe, sgs);
    EXPECT_LE(measure_fit_error(map, sgs).irradiance_rmse, 0.03) << "warm, " << label(p);
  }
}

// A small sun is one lobe: exactly one sharp lobe near it, on its direction within a fraction of
// a degree, carrying the disc's power, L_sun · 2π(1 − cos r) (procedural_sky.h), within a few %.
TEST(SkyFit, ASmallSunIsOneLobeAtItsDirectionWithItsPower) {
  for (double elev : {5.0, 20.0, 60.0})
    for (double size : {0.53, 2.0}) {
      SkyParams p;
      p.elevation_deg = elev, p.size_deg = size, p.azimuth_deg = 37.3;
      const EnvMap map = procedural_sky(p);
      const glm::dvec3 sun = sun_direction(p);
      const glm::dvec3 L = sun_radiance(p);
      const double disc_power = (L.r + L.g + L.b) / 3.0 * 2.0 * std::numbers::pi * (1.0 - std::cos(0.5 * size * kDeg));
      const SgLighting sgs = fit_sgs(map);
      int sharp_near_sun = 0;
      const SphericalGaussian* on_sun = nullptr;
      for (const auto& g : sgs)
        if (g.sharpness >= 100.0 && glm::dot(g.axis, sun) > std::cos(15.0 * kDeg) && power_of(g) > 0.01 * disc_power) {
          ++sharp_near_sun;
          on_sun = &g;
        }
      ASSERT_EQ(sharp_near_sun, 1) << "elev " << elev << " size " << size;
      const double off_deg = std::acos(std::min(1.0, glm::dot(on_sun->axis, sun))) / kDeg;
      std::printf("sun elev %g size %g: %.3f° off, power %.4f of the disc's, λ %g\n", elev, size, off_deg,
                  power_of(*on_sun) / disc_power, on_sun->sharpness);
      EXPECT_LT(off_deg, 0.2) << "elev " << elev << " size " << size;
      EXPECT_NEAR(power_of(*on_sun) / disc_power, 1.0, 0.03) << "elev " << elev << " size " << size;
    }
}
