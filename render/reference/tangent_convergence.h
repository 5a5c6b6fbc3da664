#pragma once
// How many tangent samples N_j the reference needs (docs/design.md §2: "the reference converges in
// N_j"): the check subset of the renderer (every `check_stride`-th pixel in x and y, its cloth
// pixels) is rendered at N, 2N, 4N, ... from a minimum until doubling changes it by at most a
// tolerance (relative RMSE, relative_change), up to a cap. Only the tangent samples are refined;
// the lighting's resolution (SG grid, directional samples) stays at level 0. The chosen N is the
// smallest whose subset is within the tolerance of 2N's; at the cap without that, the cap.
#include <vector>

#include "reference/scene_render.h"

namespace weft {

struct TangentConvergenceOptions {
  int minimum = 32;         // N_j to start from
  int cap = 256;            // largest N_j tried
  double tolerance = 0.01;  // relative RMSE between N and 2N over the subset's cloth pixels
};

// One doubling: the subset at `samples` against the subset at `finer` (2·samples, or the cap).
struct TangentStep {
  int samples = 0, finer = 0;
  double relative_change = 0.0;
};

struct TangentConvergence {
  int samples = 0;         // the N_j chosen
  bool converged = false;  // false: the cap was reached without a step within the tolerance
  std::vector<TangentStep> steps;
  size_t cloth_pixels = 0;  // in the check subset; none: the minimum is kept
  double seconds = 0.0;
};

// `options` are the render's own (size, SG grid, check_stride, thin_cloth); its tangent_samples
// are ignored. Throws std::invalid_argument when minimum < 1, cap < minimum or tolerance ≤ 0.
TangentConvergence converge_tangent_samples(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                                            const ReferenceLighting& lighting, ReferenceRenderOptions options,
                                            const TangentConvergenceOptions& convergence);

}  // namespace weft
