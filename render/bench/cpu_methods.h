#pragma once
// The runtime methods' C++ evaluations behind one signature, for the stability sweeps and the
// bench's stability table. One row per method. iwasaki and mizutani read baked weighting
// tables: small ones (kStressTableGrid) are baked in memory for each stress fabric on first use,
// with the paper's tangent samples (bake_selection.h); iwasaki runs without visibility here.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"

namespace weft::bench {

struct CpuShade {
  dvec3 radiance{0.0};  // premultiplied source for see-through methods
  double alpha = 0.0;   // share of what lies behind that shows through (0: opaque)
};

struct CpuMethod {
  std::string name;
  // `bsdf` holds the fabric and tangent samples; frame.n may face away from ω_o.
  std::function<CpuShade(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                         std::span<const SphericalGaussian> sgs)>
      shade;
};

// ξ, ω_o and ω_i grids of the tables the table-backed methods bake (the paper's are 48).
inline constexpr int kStressTableGrid = 16;

const std::vector<CpuMethod>& cpu_methods();

}  // namespace weft::bench
