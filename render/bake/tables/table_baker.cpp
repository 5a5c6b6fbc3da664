#include "bake/tables/table_baker.h"

#include "bake/tables/azimuthal_bake.h"
#include "bake/tables/weighting_bake.h"

namespace weft {

TableSource table_baker() {
  TableSource s;
  s.azimuthal = [] { return bake_azimuthal_table(); };
  s.weighting = [](const Fabric& fabric, std::array<int, 2> tangent_samples, int grid) {
    BakeSettings settings;
    settings.tangent_samples = tangent_samples;
    if (grid > 0) settings.xi_resolution = settings.wo_resolution = settings.wi_resolution = grid;
    return bake_weighting_tables(fabric, settings);
  };
  return s;
}

}  // namespace weft
