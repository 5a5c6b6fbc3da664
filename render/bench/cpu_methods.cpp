#include "bench/cpu_methods.h"

#include "methods/mdfrot.h"
#include "methods/sgpoint.h"
#include "methods/sheen.h"
#include "methods/thin.h"

namespace weft::bench {

namespace {
// The GPU shades the side facing the eye; so do these.
SurfaceFrame facing(SurfaceFrame f, const dvec3& wo) {
  if (glm::dot(f.n, wo) < 0.0) {
    f.n = -f.n;
    f.v = glm::cross(f.n, f.u);
  }
  return f;
}
}  // namespace

const std::vector<CpuMethod>& cpu_methods() {
  static const std::vector<CpuMethod> methods = {
      {"sgpoint",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         return CpuShade{sgpoint_radiance(b, facing(f, wo), wo, sgs), 0.0};
       }},
      {"sheen",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         return CpuShade{sheen_radiance(sheen_params(b.fabric()), facing(f, wo).n, wo, sgs), 0.0};
       }},
      {"mdfrot",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         return CpuShade{mdfrot_radiance(mdfrot_params(b.fabric()), facing(f, wo), wo, sgs), 0.0};
       }},
      {"thin",
       [](const ClothBsdf& b, const SurfaceFrame& f, const dvec3& wo, std::span<const SphericalGaussian> sgs) {
         const ThinShade s = thin_radiance(b, thin_params(b.fabric()), f, wo, sgs);
         return CpuShade{s.source, s.alpha};
       }},
  };
  return methods;
}

}  // namespace weft::bench
