#include "capture/colour_difference.h"

#include <lcms2.h>

namespace weft {

Lab lab_from_linear_srgb(const glm::dvec3& rgb) {
  // IEC 61966-2-1's linear sRGB → CIE XYZ matrix; the white is sRGB's own D65, so no adaptation.
  const cmsCIEXYZ xyz{0.4124564 * rgb.r + 0.3575761 * rgb.g + 0.1804375 * rgb.b,
                      0.2126729 * rgb.r + 0.7151522 * rgb.g + 0.0721750 * rgb.b,
                      0.0193339 * rgb.r + 0.1191920 * rgb.g + 0.9503041 * rgb.b};
  const cmsCIEXYZ d65{0.95047, 1.0, 1.08883};
  cmsCIELab lab;
  cmsXYZ2Lab(&d65, &lab, &xyz);
  return {lab.L, lab.a, lab.b};
}

double delta_e2000(const Lab& x, const Lab& y) {
  const cmsCIELab p{x.L, x.a, x.b}, q{y.L, y.a, y.b};
  return cmsCIE2000DeltaE(&p, &q, 1.0, 1.0, 1.0);
}

double delta_e2000(const glm::dvec3& x, const glm::dvec3& y) {
  return delta_e2000(lab_from_linear_srgb(x), lab_from_linear_srgb(y));
}

}  // namespace weft
