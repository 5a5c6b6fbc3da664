#pragma once
// "Model no more than the scene needs" (docs/design.md §4) for the weighting tables: given an
// error target E, pick the cheapest settings that keep each measured error under E, and say
// what was chosen. Each knob is measured against a converged version of itself:
//  - tangent samples N_j per thread: the fabric's radiance under SG lights with N_j samples
//    against N_j = 32 (docs/design.md §2's converged count), the other thread held at 32;
//  - λ levels: T at the geometric midpoint between two levels against the runtime's linear
//    interpolation in log λ, on a subsample of ξ;
//  - SVD rank per (t, λ): exact truncation error (low_rank.h), so it is simply E.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"
#include "runtime/paper_tangent_samples.h"

namespace weft {

// One line of the table `weft bake` prints.
struct SelectionRow {
  std::string setting, value;
  double error = 0.0;       // the measured error of the chosen value
  std::size_t bytes = 0;    // what it costs in the bundle (0: nothing by itself)
  double seconds = 0.0;     // time spent choosing it
};

struct SelectionResult {
  BakeSettings settings;
  std::vector<SelectionRow> rows;
};

// The error probe for tangent samples: radiance L(ξ, ω_o) = Σ_i G_λ(ξ, ω_i)·f(ω_i, ω_o)·ΔΩ
// with f = ClothBsdf::Point::integrand (summed over RGB) on an ω_i node grid (interpolated onto
// the lobe's quadrature as in the bake), ξ on a node grid, ω_o on a cell grid.
struct TangentProbe {
  int xi_resolution = 8;
  int wo_resolution = 8;
  int wi_resolution = 48;
  double lambda = 128.0;      // sharp; f between the ω_i nodes is interpolated
  int converged_samples = 32;
  std::vector<int> candidates{1, 2, 3, 4, 6, 8, 12, 16, 24, 32};
};

// Relative RMS error of the probe radiance with samples {n1, n2} against `reference` samples.
double tangent_sample_error(const Fabric& fabric, std::array<int, 2> samples, std::array<int, 2> reference,
                            const TangentProbe& probe);

struct Choice {
  int value = 0;
  double error = 0.0;
  std::vector<std::pair<int, double>> tried;  // (candidate, its error), in the order tried
};

// Smallest candidate N for thread `thread` with error ≤ target (the last candidate if none is).
Choice select_tangent_samples(const Fabric& fabric, int thread, double target, const TangentProbe& probe = {});

// Number of log-spaced λ levels over [lambda_min, lambda_max] of `base` (5, 9 or 17: spacing
// ×4, ×2, ×√2) whose interpolation error at the midpoints is ≤ target (17 if none is).
// `xi_stride` and `wo_stride` subsample the ξ and ω_o node grids for the probe.
Choice select_lambda_levels(const Fabric& fabric, const BakeSettings& base, double target, int xi_stride = 6,
                            int wo_stride = 3);

// All of the above, in order; the SVD error is set to the target.
SelectionResult select_bake_settings(const Fabric& fabric, double target, const BakeSettings& base,
                                     const BakeProgress& progress = {});

}  // namespace weft
