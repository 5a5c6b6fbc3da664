#pragma once
// Two renders of one view compared over square blocks (each covering whole weave repeats): how
// far the blocks' means are apart, sqrt(Σ|Σb − Σa|²)/sqrt(Σ|Σa|²), and how far single pixels are,
// max |b − a|/|a|. The resolved weave's tests: block means agree, pixels do not.
#include <algorithm>
#include <cmath>

#include "image/image.h"

namespace weft::test {

struct BlockComparison {
  double block_means = 0.0;  // relative difference of the block means
  double pixels = 0.0;       // largest relative difference of one pixel
};

inline BlockComparison compare_blocks(const Image& a, const Image& b, int block) {
  double err2 = 0.0, ref2 = 0.0;
  BlockComparison c;
  for (int by = 0; by + block <= a.height; by += block)
    for (int bx = 0; bx + block <= a.width; bx += block) {
      glm::dvec3 sa(0.0), sb(0.0);
      for (int y = by; y < by + block; ++y)
        for (int x = bx; x < bx + block; ++x) {
          sa += a.at(x, y);
          sb += b.at(x, y);
          const double l = glm::length(a.at(x, y));
          if (l > 0.0) c.pixels = std::max(c.pixels, glm::length(b.at(x, y) - a.at(x, y)) / l);
        }
      err2 += glm::dot(sb - sa, sb - sa);
      ref2 += glm::dot(sa, sa);
    }
  c.block_means = ref2 > 0.0 ? std::sqrt(err2 / ref2) : 0.0;
  return c;
}

}  // namespace weft::test
