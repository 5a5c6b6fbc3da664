#include "panel/hsv_color.h"

#include <algorithm>
#include <cmath>

namespace weft::input {

Hsv hsv_from_rgb(double r, double g, double b) {
  const double mx = std::max({r, g, b}), mn = std::min({r, g, b}), delta = mx - mn;
  Hsv c;
  c.v = mx;
  c.s = mx > 0 ? delta / mx : 0;
  if (delta <= 0) return c;  // grey: hue undefined, keep 0
  double h;
  if (mx == r) h = std::fmod((g - b) / delta, 6.0);
  else if (mx == g) h = (b - r) / delta + 2.0;
  else h = (r - g) / delta + 4.0;
  h *= 60.0;
  c.h = h < 0 ? h + 360.0 : h;
  return c;
}

void rgb_from_hsv(const Hsv& c, double rgb[3]) {
  const double h = std::fmod(std::fmod(c.h, 360.0) + 360.0, 360.0) / 60.0;
  const double chroma = c.v * c.s;
  const double x = chroma * (1.0 - std::fabs(std::fmod(h, 2.0) - 1.0));
  const double m = c.v - chroma;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0: r = chroma, g = x; break;
    case 1: r = x, g = chroma; break;
    case 2: g = chroma, b = x; break;
    case 3: g = x, b = chroma; break;
    case 4: r = x, b = chroma; break;
    default: r = chroma, b = x; break;
  }
  rgb[0] = r + m;
  rgb[1] = g + m;
  rgb[2] = b + m;
}

}  // namespace weft::input
