#pragma once
// Where a method gets weighting and azimuthal tables that no bundle holds. Baking them takes
// render/bake (seconds to a minute on two cores), which stays out of the kiosk's executable, so
// the offline commands hand in a baker (bake/tables/table_baker.h) and the kiosk hands in none: a
// method that needs a table it cannot get then throws instead of baking at boot.
#include <array>
#include <functional>

#include "core/fabric.h"
#include "runtime/azimuthal_table.h"
#include "runtime/weighting_tables.h"

namespace weft {

struct TableSource {
  std::function<AzimuthalTable()> azimuthal;
  // `grid`: ξ, ω_o and ω_i resolutions; 0 for the bake's default (the paper's 48).
  std::function<WeightingTables(const Fabric& fabric, std::array<int, 2> tangent_samples, int grid)> weighting;
  explicit operator bool() const { return azimuthal && weighting; }
};

}  // namespace weft
