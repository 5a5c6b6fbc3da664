#pragma once
// The acceptance measure of a fit to simulated photos: the fitted fabric and the truth rendered as
// a flat swatch under another environment map than the one photographed, compared by relative
// RMSE. Only simulated captures have a truth to compare with.
#include <array>
#include <string>

#include "core/fabric.h"
#include "lighting/env_map.h"

namespace weft {

struct AppearanceCheckOptions {
  int elevations = 3;        // view elevations, spread over 30°–70° above the swatch
  int turns = 4;             // swatch turns, spread over 360°
  int tangent_samples = 32;  // N_j per thread, as the simulation renders
  int light_cells = 64;      // the map's directional samples, as the simulation lights
};

// sqrt(mean |fitted − truth|²) / sqrt(mean |truth|²) over every view, turn and channel of the
// swatch's radiance under `map` (capture_simulation.h's evaluation). Throws std::invalid_argument
// when the truth renders black.
double appearance_relative_rmse(const Fabric& truth, const Fabric& fitted, const EnvMap& map,
                                const AppearanceCheckOptions& options = {});

// Each thread's colour A (albedo × albedo_scale, as the model reads it) of the fit against the
// truth's, in CIEDE2000 (capture/colour_difference.h).
std::array<double, 2> thread_delta_e2000(const Fabric& truth, const Fabric& fitted);

// A check as `weft capture DIR --check-map MAP --truth TRUTH` records it in the fitted file.
struct AppearanceCheck {
  std::string map;     // as named on the command line
  std::string truth;   // the truth fabric's name
  double relative_rmse = 0;
  int views = 0;       // elevations × turns
  std::array<double, 2> thread_delta_e2000{};
  // The fitted ends and picks per cm over the truth's (1 where the fit kept its family's and the
  // family's are the truth's).
  double ends_ratio = 1, picks_ratio = 1;
};

// The measures of `fitted` against `truth`: the relative RMSE under `map` (named `map_name`),
// each thread's ΔE2000, the thread counts' ratios.
AppearanceCheck check_appearance(const Fabric& truth, const Fabric& fitted, const EnvMap& map, const std::string& map_name,
                                 const AppearanceCheckOptions& options = {});

}  // namespace weft
