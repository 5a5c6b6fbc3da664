// render/lighting: the procedural sky (sun power in closed form, symmetry, ground), rotated
// maps, and environment specs.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lighting/env_spec.h"
#include "lighting/fit_error.h"
#include "lighting/procedural_sky.h"

using namespace weft;
using glm::dvec3;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// The map with only the sky dome (texel-centre radiance above the horizon, nothing below).
EnvMap sky_only(const SkyParams& p, const EnvMap& like) {
  EnvMap m(like.width, like.height);
  for (int y = 0; y < m.height / 2; ++y)
    for (int x = 0; x < m.width; ++x) m.at(x, y) = glm::vec3(sky_radiance(p, m.direction(x, y)));
  return m;
}

dvec3 horizontal_irradiance(const EnvMap& m) {
  const dvec3 up(0, 0, 1);
  return irradiance(m, std::span<const dvec3>(&up, 1))[0];
}

// Σ Ω L over the map: radiant power per unit area of a unit sphere.
dvec3 power(const EnvMap& m) {
  dvec3 sum(0.0);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) sum += m.solid_angle(y) * dvec3(m.at(x, y));
  return sum;
}

void expect_rel(const dvec3& got, const dvec3& want, double tol, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c] / want[c], 1.0, tol) << what << " channel " << c;
}
}  // namespace

// ∫_disc L_sun (ω·z) dω = L_sun π sin²r sin(elevation) = E_n sin(elevation) while the whole disc is up.
TEST(ProceduralSky, SunIrradianceOnHorizontalPlaneIsNormalIrradianceTimesSinElevation) {
  for (double elev : {3.0, 10.0, 60.0})
    for (double size : {0.53, 3.0}) {
      SkyParams p;
      p.elevation_deg = elev, p.size_deg = size, p.azimuth_deg = 17.0;
      p.width = size < 1.0 ? 1024 : 512;
      const EnvMap m = procedural_sky(p);
      const dvec3 sun_part = horizontal_irradiance(m) - horizontal_irradiance(sky_only(p, m));
      expect_rel(sun_part, sun_normal_irradiance(p) * std::sin(elev * kDeg), 0.01,
                 "elev " + std::to_string(elev) + " size " + std::to_string(size));
    }
}

// At elevation 0 the horizon cuts the disc in half: half its power, Ω_disc = 2π(1 − cos r).
TEST(ProceduralSky, SunOnTheHorizonShowsHalfItsDisc) {
  SkyParams p;
  p.elevation_deg = 0.0, p.size_deg = 2.0;
  const EnvMap m = procedural_sky(p);
  const dvec3 sun_power = power(m) - power(sky_only(p, m));
  // Subtract the ground (lower rows), which sky_only leaves black.
  dvec3 ground(0.0);
  for (int y = m.height / 2; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) ground += m.solid_angle(y) * dvec3(m.at(x, y));
  const double r = 0.5 * p.size_deg * kDeg;
  expect_rel(sun_power - ground, 0.5 * sun_radiance(p) * 2.0 * kPi * (1.0 - std::cos(r)), 0.02, "half disc");
}

// The ground is Lambertian with the given albedo, lit by everything above the horizon.
TEST(ProceduralSky, GroundRadianceIsAlbedoTimesHorizontalIrradianceOverPi) {
  SkyParams p;
  p.elevation_deg = 25.0, p.ground_albedo = 0.3, p.width = 256;
  const EnvMap m = procedural_sky(p);
  const dvec3 e = horizontal_irradiance(m);
  expect_rel(dvec3(m.at(10, m.height - 3)), 0.3 * e / kPi, 1e-5, "ground");
  p.ground_albedo = 0.0;
  EXPECT_EQ(procedural_sky(p).at(10, m.height - 3), glm::vec3(0.0f));
}

// The sky is mirror-symmetric about the sun's vertical plane: with the sun at azimuth 0 (+X)
// the mirror y → −y maps column x to W − 1 − x.
TEST(ProceduralSky, MirrorSymmetricAboutTheSunsVerticalPlane) {
  SkyParams p;
  p.elevation_deg = 12.0, p.width = 256, p.size_deg = 3.0;
  const EnvMap m = procedural_sky(p);
  for (int y = 0; y < m.height; y += 7)
    for (int x = 0; x < m.width; x += 5) {
      const glm::vec3 a = m.at(x, y), b = m.at(m.width - 1 - x, y);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-5f * (1.0f + a[c])) << x << "," << y;
    }
  // The brightest texel is the sun's.
  size_t best = 0;
  for (size_t i = 0; i < m.texels.size(); ++i)
    if (m.texels[i].g > m.texels[best].g) best = i;
  const dvec3 d = m.direction(static_cast<int>(best % m.width), static_cast<int>(best / m.width));
  EXPECT_GT(glm::dot(d, sun_direction(p)), std::cos(2.0 * kDeg));
}

// A low sun through more air is dimmer and redder; the sky brightens toward the sun.
TEST(ProceduralSky, LowSunIsDimmerAndRedder) {
  SkyParams low, high;
  low.elevation_deg = 2.0, high.elevation_deg = 50.0;
  const dvec3 el = sun_normal_irradiance(low), eh = sun_normal_irradiance(high);
  EXPECT_LT(el.g, eh.g);
  EXPECT_GT(el.r / el.b, eh.r / eh.b);
  const dvec3 s = sun_direction(high);
  const dvec3 near_sun = glm::normalize(s + dvec3(0.1, 0.0, 0.0) - dvec3(0, 0, 0.05));
  const dvec3 away = glm::normalize(dvec3(-s.x, -s.y, s.z));
  EXPECT_GT(sky_radiance(high, near_sun).g, sky_radiance(high, away).g);
}

// Rotating about +Z: a whole-texel shift equals the sky generated with its sun turned, and any
// angle keeps each row's power (hence the irradiance of a horizontal plane).
TEST(RotatedMap, MatchesTheRotatedSkyAndKeepsIrradiance) {
  SkyParams p;
  p.elevation_deg = 15.0, p.width = 256, p.size_deg = 4.0;
  const EnvMap m = procedural_sky(p);
  SkyParams q = p;
  q.azimuth_deg = 90.0;
  const EnvMap turned = procedural_sky(q), rotated = rotate_about_z(m, 90.0);
  for (size_t i = 0; i < m.texels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(rotated.texels[i][c], turned.texels[i][c], 1e-4f * (1.0f + turned.texels[i][c])) << i;
  const EnvMap odd = rotate_about_z(m, 37.3);
  expect_rel(horizontal_irradiance(odd), horizontal_irradiance(m), 1e-5, "horizontal");
  // A tilted normal turned with the map sees the same irradiance (to the interpolation's blur).
  const dvec3 n(0.6, 0.0, 0.8);
  const double a = 37.3 * kDeg;
  const dvec3 nr(0.6 * std::cos(a), 0.6 * std::sin(a), 0.8);
  expect_rel(irradiance(odd, std::span<const dvec3>(&nr, 1))[0], irradiance(m, std::span<const dvec3>(&n, 1))[0],
             0.01, "tilted");
}

TEST(EnvSpec, ParsesSkiesRotationsAndFiles) {
  const EnvSpec s = parse_env_spec("sky:elev=5,size=0.53,haze=3,azim=10@90");
  EXPECT_EQ(s.kind, EnvSpec::Kind::sky);
  EXPECT_DOUBLE_EQ(s.sky.elevation_deg, 5.0);
  EXPECT_DOUBLE_EQ(s.sky.turbidity, 3.0);
  EXPECT_DOUBLE_EQ(s.sky.azimuth_deg, 100.0);
  EXPECT_EQ(parse_env_spec("sky").kind, EnvSpec::Kind::sky);
  const EnvSpec r = parse_env_spec("studio@-45");
  EXPECT_EQ(r.kind, EnvSpec::Kind::file);
  EXPECT_EQ(r.name, "studio");
  EXPECT_DOUBLE_EQ(r.rotation_deg, -45.0);
  EXPECT_EQ(parse_env_spec("/maps/a@2x.exr").name, "/maps/a@2x.exr");  // not a rotation
  EXPECT_FALSE(is_env_spec("studio"));
  EXPECT_TRUE(is_env_spec("studio@90"));
  EXPECT_EQ(env_spec_label("studio@90"), "studio_r90");
  EXPECT_EQ(env_spec_label("sky:elev=5,haze=6"), "sky_e5_h6");
  EXPECT_EQ(env_spec_label("/x/y/dusk.exr"), "dusk");
  EXPECT_EQ(env_spec_file("sky:elev=5", "/a"), std::filesystem::path());
  EXPECT_EQ(env_spec_file("studio@90", "/a"), std::filesystem::path("/a/studio.exr"));
}

TEST(EnvSpec, BadSpecsSayWhatIsWrong) {
  auto message = [](const std::string& spec) {
    try {
      parse_env_spec(spec);
    } catch (const EnvSpecError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("sky:elev=95").find("elev"), std::string::npos);
  EXPECT_NE(message("sky:elev=-1").find("elev"), std::string::npos);
  EXPECT_NE(message("sky:size=0").find("size"), std::string::npos);
  EXPECT_NE(message("sky:haze=20").find("haze"), std::string::npos);
  EXPECT_NE(message("sky:albedo=2").find("albedo"), std::string::npos);
  EXPECT_NE(message("sky:width=102").find("width"), std::string::npos);
  EXPECT_NE(message("sky:sun=3").find("unknown sky parameter 'sun'"), std::string::npos);
  EXPECT_NE(message("sky:elev=abc").find("not a number"), std::string::npos);
  EXPECT_NE(message("sky:elev").find("key=value"), std::string::npos);
  EXPECT_NE(message("@90").find("no map"), std::string::npos);
}

TEST(EnvSpec, JoinsSkyParametersSplitAtCommas) {
  const auto v = join_env_specs({"studio", "sky:elev=5", "size=1", "haze=4", "city@90", "sky", "elev=3", "x.exr"});
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0], "studio");
  EXPECT_EQ(v[1], "sky:elev=5,size=1,haze=4");
  EXPECT_EQ(v[2], "city@90");
  EXPECT_EQ(v[3], "sky:elev=3");
  EXPECT_EQ(v[4], "x.exr");
}
