#include "runtime/paper_tangent_samples.h"

#include <algorithm>

namespace weft {

std::array<int, 2> paper_tangent_samples(const Fabric& fabric) {
  auto starts = [&](const char* prefix) { return fabric.name.rfind(prefix, 0) == 0; };
  int total = 6;  // linen, and any fabric the paper does not list
  if (starts("polyester")) total = 16;
  else if (starts("silk")) total = 10;  // crepe de chine and shot
  else if (starts("velvet")) total = 8;
  auto straight = [&](int j) {
    const auto& o = fabric.threads[j].curve.offsets_deg();
    return std::all_of(o.begin(), o.end(), [&](double x) { return x == o.front(); });
  };
  const bool s0 = straight(0), s1 = straight(1);
  if (s0 && s1) return {1, 1};
  if (s1) return {total - 1, 1};
  if (s0) return {1, total - 1};
  return {total / 2, total - total / 2};
}

}  // namespace weft
