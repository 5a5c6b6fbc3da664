#pragma once
// Filament's image-based lighting for a case, made the way a Filament application makes it: the
// lighting written as an equirectangular EXR, then Filament's own `cmgen` turns it into a KTX
// cubemap prefiltered per roughness with the irradiance's spherical harmonics in its metadata.
//
// The lighting is the case's fitted SGs, the same light Weft's rungs and the bench's reference
// see, so the peer's error is its method's, not the fit's.
//
// Directions: the peer draws in Weft's world frame (z up). cmgen reads equirect pixel (x, y) as
// the direction s = (cos φ sin θ, sin φ, cos φ cos θ) with θ = (2x/(W−1) − 1)π and
// φ = (1 − 2y/(H−1))π/2, and Filament's shaders then see it at (−s_x, s_y, s_z) (cmgen mirrors
// its cubemaps for Filament's sampling); the writer puts at each pixel the light arriving from
// that world direction, so no rotation is set on the light.
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

#include "core/spherical_gaussian.h"

namespace weft::peer {

// cmgen failed or wrote nothing: what() names the command and its exit status.
class IblError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The world direction Filament shades with for equirect pixel position (x, y) (continuous:
// pixel centres at +0.5) of a width×height map, as described above.
glm::dvec3 cmgen_direction(double x, double y, int width, int height);

// Writes radiance(world direction) as a width×height equirect EXR, each pixel the mean of
// supersample² point values over it (SGs sharper than a pixel keep their power).
void write_cmgen_equirect(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, int width, int height,
                          int supersample, const std::filesystem::path& exr);

// The case's lighting through cmgen: writes dir/lighting.exr, runs cmgen into dir, returns the
// KTX (prefiltered cubemap, SH in its metadata). `cube_size`: cmgen's --size; `map_width`: the
// EXR's width (height half of it); the default 1024 makes a pixel 0.35°, five pixels across the
// sharpest sun the fits give (λ ≈ 1000). `sh_window`: cmgen's --sh-window; its default, "auto",
// damps the SH's higher bands until the irradiance is nowhere negative (what an application
// ships); "no" keeps the plain projection (the smoke test's closed form).
std::filesystem::path make_ibl_ktx(const SgLighting& sgs, const std::filesystem::path& dir, int cube_size = 256,
                                   int map_width = 1024, const std::string& sh_window = "auto");

}  // namespace weft::peer
