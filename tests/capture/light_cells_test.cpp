// The fit's lights from a map: every watt above the horizon kept, none below; a small lamp kept
// at the finest cells' size and direction, a dim sky at the coarsest.
#include <gtest/gtest.h>

#include "capture/light_cells.h"

namespace {

// A uniform sky of radiance 0.05 (each coarse cell under the 0.4 % share that splits a cell), a lamp of radiance 500 over the 2×2 texels at (40, 12) of a
// 128×64 map, and ground of radiance 0.3 below the horizon.
weft::EnvMap sky_and_lamp() {
  weft::EnvMap map(128, 64);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) map.at(x, y) = glm::vec3(map.direction(x, y).z > 0 ? 0.05f : 0.3f);
  for (int y = 12; y < 14; ++y)
    for (int x = 40; x < 42; ++x) map.at(x, y) = glm::vec3(500.0f);
  return map;
}

}  // namespace

TEST(LightCells, KeepThePowerAboveTheHorizonAndRefineOnlyTheLamp) {
  const weft::EnvMap map = sky_and_lamp();
  glm::dvec3 expected(0);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      if (map.direction(x, y).z > 0) expected += glm::dvec3(map.at(x, y)) * map.solid_angle(y);
  const auto lights = weft::light_cells(map);
  glm::dvec3 total(0);
  for (const auto& l : lights) {
    EXPECT_GT(l.direction.z, 0);
    total += l.power;
  }
  EXPECT_NEAR(total.r, expected.r, 1e-4 * expected.r);
  // 16 × 4 coarse cells above the horizon; the lamp's one split into 4, and the quarter with the
  // lamp into 4 again: 64 − 1 + 4 − 1 + 4 = 70.
  EXPECT_EQ(lights.size(), 70u);
  // The brightest light is the lamp: its power (the texels' radiance × solid angle, plus the sky
  // in its 2×2-texel cell, which is the lamp's own) along its centre.
  const auto* lamp = &lights[0];
  for (const auto& l : lights)
    if (l.power.r > lamp->power.r) lamp = &l;
  const double lamp_power = 500.0 * 2 * (map.solid_angle(12) + map.solid_angle(13));
  EXPECT_NEAR(lamp->power.r, lamp_power, 1e-3 * lamp_power);
  const glm::dvec3 centre = weft::uv_to_direction({41.0 / 128, 1.0 - 13.0 / 64});
  EXPECT_GT(glm::dot(lamp->direction, centre), std::cos(glm::radians(1.0)));
  EXPECT_THROW(weft::light_cells(map, {16, 48, 0.004}), std::invalid_argument);
}
