#pragma once
// Stress cases that push the methods past their assumptions: narrow
// lights (λ = 10⁴), a window (a strip of narrow SGs: narrow anisotropic light), grazing views (θ_o to 89°), very glossy threads (γ_s = 1°), velvet pile
// at 90°, back light, a sheer (voile) front-lit, back-lit and grazing, an all-black and a
// single-hot-texel environment. Each case is a fabric,
// a set of SGs and a set of (frame, ω_o) points; a sweep evaluates a method at every point,
// counts non-finite and negative values, and optionally measures the relative RMSE against
// the canonical model integrated by quadrature (reference/sg_quadrature.h; for `thin`, its
// own reference: (1 − α)·canonical + reference/thin_quadrature.h; so for `sheer`).
// Not covered here: the thin-occluder case (scene visibility): the bench measures it on the
// `teapot` scene's images (bench/shadow_mask.h); iwasaki runs here without visibility.
#include <string>
#include <vector>

#include "bench/cpu_methods.h"
#include "core/fabric.h"

namespace weft::bench {

struct StressPoint {
  SurfaceFrame frame;
  dvec3 wo;
};

struct StressCase {
  std::string name;
  std::string notes;  // what it pushes
  Fabric fabric;
  SgLighting sgs;
  std::vector<StressPoint> points;
};

// The cases, for presets in `fabric_dir`; `points_per_case` views each (deterministic).
std::vector<StressCase> stress_cases(const std::filesystem::path& fabric_dir, int points_per_case);

struct StressResult {
  int evaluations = 0;
  int non_finite = 0;   // NaN or Inf in any channel (or alpha)
  int negative = 0;     // a channel below 0 (or alpha outside [0, 1])
  bool measured = false;
  double relative_rmse = 0.0;  // sqrt(mean |x−r|²)/mean(r) over points and channels
  double reference_mean = 0.0;
  double max_abs = 0.0;        // largest |radiance| seen
};

// The canonical model at every point of the case by quadrature (16 tangent samples per thread,
// 1 % tolerance, grids up to 256 × 512 per SG): computed once per case, shared by the methods.
std::vector<dvec3> stress_reference(const StressCase& c);

// `reference` (from stress_reference, or null): also measure the error against it.
StressResult run_stress(const CpuMethod& method, const StressCase& c, const std::vector<dvec3>* reference,
                        int tangent_samples = 16);

}  // namespace weft::bench
