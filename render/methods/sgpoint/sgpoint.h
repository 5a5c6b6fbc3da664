#pragma once
// Method `sgpoint` on the CPU: each SG as a directional light along its axis with the SG's
// whole power, shading with the full model (ClothBsdf::Point::integrand). The C++ side of
// methods/sgpoint/sgpoint.frag, whose model part tests/gpu/microcylinder_parity_test.cpp pins.
#include <span>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"

namespace weft {

dvec3 sgpoint_radiance(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                       std::span<const SphericalGaussian> sgs);

}  // namespace weft
