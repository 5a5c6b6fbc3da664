#include "methods/sgpoint/sgpoint.h"

#include "methods/sg_lights.h"

namespace weft {

dvec3 sgpoint_radiance(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                       std::span<const SphericalGaussian> sgs) {
  auto point = bsdf.at(frame);
  dvec3 l(0.0);
  for (const auto& g : sgs) l += sg_power(g) * point.integrand(g.axis, wo);
  return l;
}

}  // namespace weft
