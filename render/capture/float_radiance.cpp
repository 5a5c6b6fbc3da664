#include "capture/float_radiance.h"

#include <cmath>

#include "capture/swatch_frame.h"
#include "core/cloth_bsdf.h"
#include "core/weave_layout.h"

namespace weft {

FloatRadiance float_radiance(const Fabric& fabric, const std::vector<FitLight>& lights, double turn, int arc_bins,
                             int tangent_samples) {
  const SurfaceFrame frame = swatch_frame(turn);
  const glm::dvec3 wo(0, 0, 1);
  const ClothBsdf bsdf(fabric, tangent_samples);
  FloatRadiance out{std::vector<glm::dvec3>(arc_bins, glm::dvec3(0)), std::vector<glm::dvec3>(arc_bins, glm::dvec3(0))};
#pragma omp parallel for schedule(static)
  for (int b = 0; b < 2 * arc_bins; ++b) {
    const int j = b / arc_bins, k = b % arc_bins;
    ClothBsdf::Point point = bsdf.at(frame);
    const double tilt = weave_tilt(fabric, WeaveSample{j, (k + 0.5) / arc_bins, 0.0});
    glm::dvec3 sum(0);
    for (const FitLight& l : lights) sum += l.power * point.resolved_integrand(j, tilt, l.direction, wo);
    out[j][k] = sum;
  }
  return out;
}

}  // namespace weft
