#pragma once
// A procedural clear sky as an equirect EnvMap in Weft's frame (+Z up, docs/design.md §3): the sky
// dome after Preetham, Shirley and Smits 1999 (Perez distribution of luminance and chromaticity
// with their turbidity fits, zenith luminance and chromaticity), a sun disc of uniform
// radiance, and a Lambertian ground lit by both. Units: the paper's kcd/m² for the sky, the
// same for the sun's radiance (its irradiance in klx).
//
// The sun disc (angular radius r = size/2 around s) has the radiance that gives it the normal
// irradiance E_n exactly: L_sun = E_n / (π sin² r), since ∫_disc (ω·s) dω = π sin² r. Its
// irradiance on a horizontal plane is then E_n·sin(elevation) while the disc is above the
// horizon. E_n = 127 klx · τ(m) with m the Kasten–Young air mass and τ a per-channel
// transmittance that falls with turbidity (reddening a low sun). Texels the disc's edge crosses
// are supersampled so that its power holds at any size the map resolves.
#include <string>

#include <glm/glm.hpp>

#include "lighting/env_map.h"

namespace weft {

struct SkyParams {
  double elevation_deg = 20.0;   // sun above the horizon, [-5, 90]
  double azimuth_deg = 0.0;      // sun azimuth from +X toward +Y
  double size_deg = 0.53;        // the sun disc's angular diameter, (0, 20]
  double turbidity = 3.0;        // haze: Preetham's T, [1.7, 10]
  double ground_albedo = 0.2;    // the ground below the horizon, [0, 1]
  int width = 1024;              // map width (height = width / 2), [64, 4096], even
};

// Throws std::invalid_argument naming the parameter out of range.
void validate(const SkyParams& p);

// Unit direction toward the sun's centre.
glm::dvec3 sun_direction(const SkyParams& p);
// The sun disc's normal irradiance E_n (RGB) and its uniform radiance E_n / (π sin² r).
glm::dvec3 sun_normal_irradiance(const SkyParams& p);
glm::dvec3 sun_radiance(const SkyParams& p);
// The sky dome's radiance toward an upward direction d (d.z > 0), sun disc excluded.
glm::dvec3 sky_radiance(const SkyParams& p, const glm::dvec3& d);

// The whole map: sky above the horizon, ground below, sun disc on top.
EnvMap procedural_sky(const SkyParams& p);

}  // namespace weft
