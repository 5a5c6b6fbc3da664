#pragma once
// What the methods' C++ evaluations behind the registry share: the side of the surface they
// shade, and the small weighting and azimuthal tables the table-backed methods (iwasaki,
// mizutani) read, taken from the caller's TableSource on first use and kept.
#include "runtime/azimuthal_table.h"
#include "runtime/weighting_tables.h"
#include "core/cloth_bsdf.h"
#include "runtime/table_source.h"

namespace weft::methods {

// ξ, ω_o and ω_i grids of the tables the table-backed methods bake (the paper's are 48).
inline constexpr int kStressTableGrid = 16;

// The GPU shades the side facing the eye; so do the C++ evaluations.
SurfaceFrame facing(SurfaceFrame f, const dvec3& wo);

// Tables for a fabric, baked once per preset name with the paper's tangent samples (they depend
// on the thread curves, not on A or γ), and the matching BSDF (the tables' tangent samples, the
// fabric's thread parameters). Thread-safe.
struct TableBsdf {
  const WeightingTables* tables;
  ClothBsdf bsdf;
};
// Throws std::runtime_error when `tables` cannot make them.
TableBsdf stress_table_bsdf(const Fabric& fabric, const TableSource& tables);
const AzimuthalTable& stress_azimuthal_table(const TableSource& tables);

}  // namespace weft::methods
