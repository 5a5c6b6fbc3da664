#pragma once
// What a showroom built on Filament would set for one of Weft's fabrics: the parameters of
// Filament's cloth material (peer_cloth.mat, shading model `cloth`).
//
// The mapping is the `sheen` rung's (methods/sheen/sheen.h), since that rung draws the same
// lobes (Lambert plus Charlie sheen with Neubelt visibility), so the peer and the rung differ
// only in how they are lit (Filament's IBL against per-SG lights) and in the engine:
//  - baseColor  = the threads' albedo, weighted by coverage (Filament's cloth diffuse);
//  - sheenColor = the fibres' normal-incidence Fresnel reflectance, weighted the same way;
//  - roughness  = Filament's perceptual roughness, √α of the rung's α = (Σ w_j γ_s,j)², i.e. the
//    threads' surface-lobe width in radians (Filament clamps it below at 0.089 itself).
// subsurfaceColor stays unset: Weft's fabrics have nothing that matches Filament's wrap diffuse.
#include <glm/glm.hpp>

#include "core/fabric.h"

namespace weft::peer {

struct FilamentCloth {
  glm::dvec3 base_colour{0.5};
  glm::dvec3 sheen_colour{0.04};
  double roughness = 0.5;  // perceptual
};

FilamentCloth filament_cloth(const Fabric& fabric);

}  // namespace weft::peer
