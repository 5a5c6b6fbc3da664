#pragma once
// The runtime methods' C++ evaluations behind one signature, for the stability sweeps and the
// bench's stability table: the registry's (methods/registry.h), one row per method that has its
// own, in the table's order (kStabilityOrder, then any other in the registry's order). iwasaki
// and mizutani read baked weighting tables: small ones (kStressTableGrid) are baked in memory for
// each stress fabric on first use, with the paper's tangent samples (bake_selection.h); iwasaki
// runs without visibility here.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "methods/cpu_evaluation.h"
#include "methods/runtime_method.h"

namespace weft::bench {

using CpuShade = methods::CpuShade;

struct CpuMethod {
  std::string name;
  // The registry's evaluation with the bench's tables (baked on first use).
  std::function<CpuShade(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                         std::span<const SphericalGaussian> sgs)>
      shade;
};

// ξ, ω_o and ω_i grids of the tables the table-backed methods bake (the paper's are 48).
inline constexpr int kStressTableGrid = methods::kStressTableGrid;

// The stability table's rows by registry name.
inline constexpr const char* kStabilityOrder[] = {"iwasaki", "mizutani", "sgpoint", "sheen", "mdfrot", "thin", "sheer"};

const std::vector<CpuMethod>& cpu_methods();

}  // namespace weft::bench
