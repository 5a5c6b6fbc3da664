#include "capture/light_cells.h"

#include <stdexcept>

#include "image/tone_map.h"

namespace weft {

namespace {

struct Cell {
  glm::dvec3 power{0.0}, weighted{0.0}, plain{0.0};
  double luminous = 0;
  void add(const Cell& c) {
    power += c.power;
    weighted += c.weighted;
    plain += c.plain;
    luminous += c.luminous;
  }
};

}  // namespace

std::vector<FitLight> light_cells(const EnvMap& map, const LightCellOptions& o) {
  int levels = 1;
  while ((o.coarsest << (levels - 1)) < o.finest) ++levels;
  if (o.coarsest < 2 || o.coarsest % 2 || (o.coarsest << (levels - 1)) != o.finest || o.finest > map.width ||
      map.width % o.finest || map.height % (o.finest / 2))
    throw std::invalid_argument("light_cells: the cell grids do not nest in the map");
  // The finest grid from the texels, each coarser one from the one below it.
  std::vector<std::vector<Cell>> grid(levels);
  const int fw = o.finest, fh = o.finest / 2;
  grid[levels - 1].resize(static_cast<size_t>(fw) * fh);
  double above = 0;
  for (int y = 0; y < map.height; ++y) {
    const double omega = map.solid_angle(y);
    for (int x = 0; x < map.width; ++x) {
      const glm::dvec3 L(map.at(x, y)), d = map.direction(x, y);
      const double lum = std::max(luminance(L), 0.0) * omega;
      Cell& c = grid[levels - 1][static_cast<size_t>(y * fh / map.height) * fw + x * fw / map.width];
      c.add({L * omega, lum * d, omega * d, lum});
      if (d.z > 0) above += lum;
    }
  }
  for (int l = levels - 2; l >= 0; --l) {
    const int w = o.coarsest << l, h = w / 2;
    grid[l].resize(static_cast<size_t>(w) * h);
    for (int y = 0; y < 2 * h; ++y)
      for (int x = 0; x < 2 * w; ++x) grid[l][static_cast<size_t>(y / 2) * w + x / 2].add(grid[l + 1][static_cast<size_t>(y) * 2 * w + x]);
  }
  std::vector<FitLight> out;
  auto emit = [&](auto&& self, int l, int x, int y) -> void {
    const int w = o.coarsest << l;
    const Cell& c = grid[l][static_cast<size_t>(y) * w + x];
    if (l + 1 < levels && c.luminous > o.share * above) {
      for (int k = 0; k < 4; ++k) self(self, l + 1, 2 * x + (k & 1), 2 * y + (k >> 1));
      return;
    }
    if (c.power == glm::dvec3(0.0)) return;
    const glm::dvec3 d = glm::normalize(glm::length(c.weighted) > 0 ? c.weighted : c.plain);
    if (d.z > 0) out.push_back({d, c.power});
  };
  for (int y = 0; y < o.coarsest / 2; ++y)
    for (int x = 0; x < o.coarsest; ++x) emit(emit, 0, x, y);
  return out;
}

}  // namespace weft
