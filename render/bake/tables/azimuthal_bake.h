#pragma once
// Computes the azimuthal table T_m (runtime/azimuthal_table.h holds its definition and
// lookup) by quadrature, and measures how well its nodes interpolate.
#include "runtime/azimuthal_table.h"

namespace weft {

AzimuthalTable bake_azimuthal_table(const AzimuthalTableSettings& settings = {});

// Worst |interpolated − integral| / Z(λ') at the centres of every `stride`-th cell (the
// farthest points from the nodes), powers 1, 6 and 10, by the bake's own quadrature.
double azimuthal_interpolation_error(const AzimuthalTable& table, int stride = 4);

}  // namespace weft
