#include "core/normal_map_frame.h"

#include <algorithm>
#include <cmath>

namespace weft {

dvec3 tangent_space_normal(dvec3 texel, double scale) {
  dvec3 t = 2.0 * texel - 1.0;
  auto flat_codes_to_zero = [](double x) {
    return std::copysign(std::max(std::abs(x) - kNormalMapHalfStep, 0.0) / (1.0 - kNormalMapHalfStep), x);
  };
  t.x = scale * flat_codes_to_zero(t.x);
  t.y = scale * flat_codes_to_zero(t.y);
  t.z = std::max(t.z, kMinNormalMapZ);
  return glm::normalize(t);
}

SurfaceFrame normal_mapped_frame(const SurfaceFrame& frame, dvec3 t) {
  // Rodrigues' rotation from z to t, in the frame's own coordinates: with k = z × t = (−t.y, t.x, 0)
  // and c = t.z, R = I + [k]× + [k]×² / (1 + c). Its columns are the turned u, v and n.
  const double c = t.z, d = 1.0 / (1.0 + c);
  const dvec3 ru(1.0 - t.x * t.x * d, -t.x * t.y * d, -t.x);
  const dvec3 rv(-t.x * t.y * d, 1.0 - t.y * t.y * d, -t.y);
  auto world = [&](dvec3 l) { return l.x * frame.u + l.y * frame.v + l.z * frame.n; };
  SurfaceFrame out;
  out.n = glm::normalize(world(t));
  out.u = glm::normalize(world(ru));
  out.v = glm::cross(out.n, out.u);
  return out;
}

}  // namespace weft
