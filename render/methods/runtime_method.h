#pragma once
// One runtime method as the registry lists it (docs/design.md §4): its name and traits, what makes its
// GPU side, and its C++ evaluation. Each method's folder defines its entry (<name>_method.h).
#include <functional>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/cloth_bsdf.h"
#include "runtime/table_source.h"
#include "core/spherical_gaussian.h"
#include "methods/cloth_method.h"

namespace weft::methods {

// How a method uses seed 000's tables (a bundle's IwasakiBundleData).
enum class Seed000Tables {
  unused,
  read_when_given,  // reads their W tables when the bundle has them for its samples, else bakes its own
  required,         // cannot draw without them
};

// What the bench measures a method's accuracy against.
enum class BenchReference {
  opaque,      // the reference with opaque cloth
  thin_layer,  // the reference with cloth as seed 004's thin layer (ReferenceRenderOptions::thin_cloth)
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
  Seed000Tables seed000 = Seed000Tables::unused;
  // Reads the bundle's per-vertex visibility masks (`weft bake` writes them unless `--no-masks`).
  bool visibility_masks = false;
  BenchReference reference = BenchReference::opaque;
  std::set<std::string> bench_scenes;  // the scenes the bench runs it on; empty: every scene
  int ladder_position = 0;             // its row on the bench's chart and report (ascending)
  int stability_position = -1;         // its row in the stability table; -1: no C++ evaluation of its own
  // The fragment shader's function parts in order, without the method's main (a parity test
  // compiles them with its own); embedded names (shaders/embedded_shaders.h).
  std::vector<std::string_view> glsl;
  GpuFactory make_gpu;
  CpuEvaluation cpu;  // empty where stability_position is -1
};

}  // namespace weft::methods
