#pragma once
// One runtime method as the registry lists it (docs/design.md §4): its name and traits, what makes its
// GPU side, and its C++ evaluation. Each method's folder defines its entry (<name>_method.h).
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/cloth_bsdf.h"
#include "runtime/shading_data.h"
#include "runtime/table_source.h"
#include "core/spherical_gaussian.h"
#include "methods/cloth_method.h"

namespace weft::methods {

// How a method uses the weighting tables (a bundle's ShadingData: W, visibility, κ).
enum class WeightingTablesUse {
  unused,
  read_when_given,  // reads their W tables when the bundle has them for its samples, else bakes its own
  required,         // cannot draw without them
};

// Where a method shades.
enum class Shading {
  per_pixel,   // every cloth fragment
  per_vertex,  // every mesh vertex, interpolated over the triangles
};

// What a method reads from the bundle's per-vertex visibility masks (`weft bake` writes them
// unless `--no-masks`).
struct MaskUse {
  bool open_share = false;   // the sharper SGs' visibility: the mask's open share V_k instead of the SDF's H
  bool broad_lobes = false;  // the sky's broad lobes by quadrature over the mask's cells
  bool any() const { return open_share || broad_lobes; }
};

// One C++ evaluation: radiance leaving the cloth towards ω_o.
struct CpuShade {
  dvec3 radiance{0.0};  // premultiplied source for see-through methods
  double alpha = 0.0;   // share of what lies behind that shows through (0: opaque)
};
// `bsdf` holds the fabric and tangent samples; frame.n may face away from ω_o. Table-backed
// methods take small tables from `tables` on first use (runtime/table_source.h).
using CpuEvaluation = std::function<CpuShade(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                                             std::span<const SphericalGaussian> sgs, const TableSource& tables)>;

using GpuFactory = std::function<std::unique_ptr<gpu::ClothMethod>(const gpu::ClothMethodSetup& setup)>;

struct RuntimeMethod {
  std::string name;
  // The cloth shows what lies behind it: drawn last, blended dst·α + src, over the SG environment.
  bool see_through = false;
  WeightingTablesUse weighting_tables = WeightingTablesUse::unused;
  Shading shading = Shading::per_pixel;
  MaskUse masks;
  // It reads the bundle's per-vertex visibility SDF and κ (shadows on the cloth).
  bool baked_visibility = false;
  // `weft run --method auto` may choose it: the kiosk takes the first such method, in the
  // registry's order, whose traits fit the bundle (kiosk/kiosk_bundle.h).
  bool kiosk_rung = false;
  // The fragment shader's function parts in order, without the method's main (a parity test
  // compiles them with its own); embedded names (shaders/embedded_shaders.h).
  std::vector<std::string_view> glsl;
  GpuFactory make_gpu;
  CpuEvaluation cpu;  // empty: no C++ evaluation of its own

  bool needs_weighting_tables() const { return weighting_tables == WeightingTablesUse::required; }
  bool reads_weighting_tables() const { return weighting_tables != WeightingTablesUse::unused; }
  bool reads_visibility_masks() const { return masks.any(); }
  // The parts of a bundle's shading data its GPU side reads (runtime/shading_data.h).
  ShadingParts bake_reads() const {
    return {reads_weighting_tables(), baked_visibility || masks.any(), masks.any()};
  }
};

}  // namespace weft::methods
