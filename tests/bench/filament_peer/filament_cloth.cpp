#include "bench/filament_peer/filament_cloth.h"

#include <cmath>

#include "methods/sheen/sheen.h"

namespace weft::peer {

FilamentCloth filament_cloth(const Fabric& fabric) {
  const SheenParams p = sheen_params(fabric);
  FilamentCloth c;
  c.base_colour = p.diffuse;
  c.sheen_colour = p.sheen_colour;
  c.roughness = std::sqrt(p.roughness);
  return c;
}

}  // namespace weft::peer
