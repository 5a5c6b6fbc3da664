#include "reference/tangent_convergence.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace weft {

namespace {

// The subset's pixels as one renderer at `samples` tangent samples sees them.
std::vector<glm::dvec3> render_subset(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                                      const ReferenceLighting& lighting, ReferenceRenderOptions options, int samples,
                                      const std::vector<std::pair<int, int>>& pixels) {
  options.tangent_samples = samples;
  options.check_convergence = false;
  const ReferenceRenderer renderer(scene, fabrics, lighting, options);
  std::vector<glm::dvec3> values(pixels.size());
#pragma omp parallel for schedule(dynamic, 8)
  for (size_t i = 0; i < pixels.size(); ++i) values[i] = renderer.pixel(pixels[i].first, pixels[i].second, 0);
  return values;
}

}  // namespace

TangentConvergence converge_tangent_samples(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                                            const ReferenceLighting& lighting, ReferenceRenderOptions options,
                                            const TangentConvergenceOptions& c) {
  if (c.minimum < 1) throw std::invalid_argument("tangent convergence: minimum must be ≥ 1");
  if (c.cap < c.minimum) throw std::invalid_argument("tangent convergence: cap must be ≥ the minimum");
  if (!(c.tolerance > 0.0)) throw std::invalid_argument("tangent convergence: tolerance must be > 0");
  const auto start = std::chrono::steady_clock::now();
  TangentConvergence res;
  res.samples = c.minimum;

  // The cloth pixels of the check subset (what a pixel sees does not depend on N_j).
  options.tangent_samples = c.minimum;
  std::vector<std::pair<int, int>> pixels;
  {
    const ReferenceRenderer probe(scene, fabrics, lighting, options);
    for (const auto& xy : probe.check_pixels())
      if (probe.kind(xy.first, xy.second) == PixelKind::cloth) pixels.push_back(xy);
  }
  res.cloth_pixels = pixels.size();
  if (pixels.empty()) {
    res.converged = true;
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return res;
  }

  std::vector<glm::dvec3> coarse = render_subset(scene, fabrics, lighting, options, c.minimum, pixels);
  for (int n = c.minimum;;) {
    if (n >= c.cap) {  // the cap itself, not within the tolerance of anything coarser
      res.samples = c.cap;
      break;
    }
    const int finer = std::min(2 * n, c.cap);
    std::vector<glm::dvec3> fine = render_subset(scene, fabrics, lighting, options, finer, pixels);
    const double change = relative_change(coarse, fine);
    res.steps.push_back({n, finer, change});
    if (change <= c.tolerance) {
      res.samples = n;
      res.converged = true;
      break;
    }
    coarse = std::move(fine);
    n = finer;
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

}  // namespace weft
