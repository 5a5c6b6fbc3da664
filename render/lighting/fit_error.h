#pragma once
// How well a set of SGs reproduces an environment map, measured two ways:
//  radiance:   relative RMSE of the radiance over the sphere, solid-angle weighted, all three
//              channels: sqrt(∫‖L−S‖²dω / 3·4π) / (∫ΣL dω / 3·4π), at the map's resolution
//              (maps wider than 1024 are first resampled to 1024×512);
//  radiance_coarse: the same after both maps are area-averaged to 64×32 (5.6° texels): the
//              scale a few SGs can hold; the full-resolution number is dominated by sources
//              smaller than any lobe (a sun of 30 000 over a few texels);
//  irradiance: relative RMSE of the diffuse irradiance E(n) = ∫ L(ω) max(n·ω, 0) dω over a
//              Fibonacci set of normals: sqrt(mean_n ‖E−E_S‖²/3) / mean_n(ΣE/3).
// The SGs are rendered into a map of the same size (texel-centre values) and both maps go
// through the same resampling and the same summation, so the discretisation is shared and
// the number measures the fit alone.
#include <span>
#include <vector>

#include "core/spherical_gaussian.h"
#include "lighting/env_map.h"

namespace weft {

struct SgFitError {
  double radiance_rmse = 0.0;
  double radiance_rmse_coarse = 0.0;
  double irradiance_rmse = 0.0;
};

struct SgFitErrorOptions {
  int irradiance_grid_width = 128;  // the maps are summed on this grid (height = width / 2)
  int normals = 1024;
};

SgFitError measure_fit_error(const EnvMap& map, std::span<const SphericalGaussian> sgs,
                             const SgFitErrorOptions& options = {});

// The SGs' radiance at every texel centre of a width × height map.
EnvMap render_sgs(std::span<const SphericalGaussian> sgs, int width, int height);

// E(n) = Σ_texels Ω L max(n·d, 0) for each normal (direct summation on the map as given).
std::vector<glm::dvec3> irradiance(const EnvMap& map, std::span<const glm::dvec3> normals);

// n nearly uniform unit directions (Fibonacci spiral), deterministic.
std::vector<glm::dvec3> fibonacci_sphere(int n);

}  // namespace weft
