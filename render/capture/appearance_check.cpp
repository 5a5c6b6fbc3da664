#include "capture/appearance_check.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "capture/capture_simulation.h"
#include "capture/colour_difference.h"
#include "capture/swatch_frame.h"
#include "core/cloth_bsdf.h"

namespace weft {

double appearance_relative_rmse(const Fabric& truth, const Fabric& fitted, const EnvMap& map,
                                const AppearanceCheckOptions& options) {
  if (options.elevations < 1 || options.turns < 1) throw std::invalid_argument("appearance check needs views");
  const std::vector<FitLight> lights = simulated_swatch_lights(map, options.light_cells);
  const ClothBsdf truth_bsdf(truth, options.tangent_samples), fitted_bsdf(fitted, options.tangent_samples);
  double diff2 = 0, truth2 = 0;
  for (int t = 0; t < options.turns; ++t) {
    const double turn = 2 * std::numbers::pi * t / options.turns;
    const SurfaceFrame frame = swatch_frame(turn);
    ClothBsdf::Point truth_point = truth_bsdf.at(frame), fitted_point = fitted_bsdf.at(frame);
    for (int e = 0; e < options.elevations; ++e) {
      // Seen from the card's bottom edge (−Y), as the photos are taken.
      const double el = glm::radians(options.elevations == 1 ? 50.0 : 30.0 + 40.0 * e / (options.elevations - 1));
      const glm::dvec3 wo(0, -std::cos(el), std::sin(el));
      const glm::dvec3 a = simulated_swatch_radiance(truth_point, lights, wo);
      const glm::dvec3 b = simulated_swatch_radiance(fitted_point, lights, wo);
      diff2 += glm::dot(b - a, b - a);
      truth2 += glm::dot(a, a);
    }
  }
  if (!(truth2 > 0)) throw std::invalid_argument("appearance check: the truth renders black under this map");
  // The sample counts cancel in the ratio of the two means.
  return std::sqrt(diff2 / truth2);
}

std::array<double, 2> thread_delta_e2000(const Fabric& truth, const Fabric& fitted) {
  return {delta_e2000(truth.threads[0].albedo, fitted.threads[0].albedo),
          delta_e2000(truth.threads[1].albedo, fitted.threads[1].albedo)};
}

AppearanceCheck check_appearance(const Fabric& truth, const Fabric& fitted, const EnvMap& map, const std::string& map_name,
                                 const AppearanceCheckOptions& options) {
  return {map_name,
          truth.name,
          appearance_relative_rmse(truth, fitted, map, options),
          options.elevations * options.turns,
          thread_delta_e2000(truth, fitted),
          fitted.weave.ends_per_cm / truth.weave.ends_per_cm,
          fitted.weave.picks_per_cm / truth.weave.picks_per_cm};
}

}  // namespace weft
