#include "core/fresnel.h"

#include <algorithm>
#include <cmath>

namespace weft {

double fresnel_dielectric(double eta, double cos_i) {
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  const double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0) return 1.0;  // total internal reflection (only for η < 1)
  const double cos_t = std::sqrt(1.0 - sin2_t);
  const double r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const double r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (r_s * r_s + r_p * r_p);
}

}  // namespace weft
