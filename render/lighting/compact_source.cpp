#include "lighting/compact_source.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace weft {

namespace {
using glm::dvec3;
double luminance(const dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }
}  // namespace

std::optional<CompactSource> find_compact_source(const EnvMap& map, const CompactSourceOptions& options,
                                                 EnvMap* without) {
  const int w = map.width, h = map.height;
  if (w < 2 || h < 1) return std::nullopt;
  size_t peak = 0;
  double peak_lum = 0.0, total = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const double l = luminance(dvec3(map.texels[i]));
      total += map.solid_angle(y) * l;
      if (l > peak_lum) peak_lum = l, peak = i;
    }
  if (!(peak_lum > 0.0)) return std::nullopt;

  // Grow the region from the peak; give up once it reaches past the radius (not compact).
  const int px = static_cast<int>(peak % w), py = static_cast<int>(peak / w);
  const dvec3 peak_dir = map.direction(px, py);
  const double cos_limit = std::cos(options.max_radius_deg * std::numbers::pi / 180.0);
  const double cut = options.threshold * peak_lum;
  std::vector<char> in_region(map.texels.size(), 0);
  std::vector<size_t> region{peak};
  in_region[peak] = 1;
  // The 8-neighbours of texel i (wrapping in x) that are not in the region yet.
  auto outside_neighbours = [&](size_t i, auto&& visit) {
    const int x0 = static_cast<int>(i % w), y0 = static_cast<int>(i / w);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int y = y0 + dy;
        if (y < 0 || y >= h || (dx == 0 && dy == 0)) continue;
        const int x = ((x0 + dx) % w + w) % w;
        const size_t j = static_cast<size_t>(y) * w + x;
        if (!in_region[j]) visit(j, x, y);
      }
  };
  bool compact = true;
  for (size_t next = 0; next < region.size() && compact; ++next)
    outside_neighbours(region[next], [&](size_t j, int x, int y) {
      if (!compact || luminance(dvec3(map.texels[j])) < cut) return;
      if (glm::dot(map.direction(x, y), peak_dir) < cos_limit) compact = false;
      in_region[j] = 1;
      region.push_back(j);
    });
  if (!compact) return std::nullopt;
  // One texel further: the texels the source's edge covers only partly (below the cut, yet far
  // above the sky) belong to it; the background is read from the ring around those.
  std::vector<size_t> ring;
  auto grow = [&](std::vector<size_t>& into) {
    const size_t n = region.size();
    for (size_t k = 0; k < n; ++k)
      outside_neighbours(region[k], [&](size_t j, int, int) {
        in_region[j] = 1;
        into.push_back(j);
      });
  };
  const size_t core = region.size();
  std::vector<size_t> edge;
  grow(edge);
  region.insert(region.end(), edge.begin(), edge.end());
  grow(ring);
  for (size_t j : ring) in_region[j] = 0;
  if (ring.empty()) return std::nullopt;  // the whole map: nothing compact about it

  CompactSource s;
  double ring_omega = 0.0;
  for (size_t i : ring) {
    const double o = map.solid_angle(static_cast<int>(i / w));
    s.background += o * dvec3(map.texels[i]);
    ring_omega += o;
  }
  s.background /= ring_omega;
  dvec3 centroid(0.0);
  double region_omega = 0.0, region_lum = 0.0;
  for (size_t k = 0; k < region.size(); ++k) {
    const size_t i = region[k];
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    const double o = map.solid_angle(y);
    const dvec3 excess = dvec3(map.texels[i]) - s.background;
    s.power += o * excess;
    centroid += o * std::max(0.0, luminance(excess)) * map.direction(x, y);
    if (k < core) region_omega += o, region_lum += o * luminance(dvec3(map.texels[i]));  // contrast: the core
  }
  s.power = glm::max(s.power, dvec3(0.0));
  const double power_lum = luminance(s.power);
  if (!(power_lum >= options.min_power_share * total) || !(power_lum > 0.0) || !(glm::length(centroid) > 0.0))
    return std::nullopt;
  if (!(region_lum / region_omega >= options.min_contrast * luminance(s.background))) return std::nullopt;
  s.direction = glm::normalize(centroid);
  double spread = 0.0, weight = 0.0;
  for (size_t i : region) {
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    const double p = map.solid_angle(y) * std::max(0.0, luminance(dvec3(map.texels[i]) - s.background));
    spread += p * (1.0 - glm::dot(map.direction(x, y), s.direction));
    weight += p;
  }
  s.spread = spread / weight;

  if (without) {
    *without = map;
    for (size_t i : region) without->texels[i] = glm::vec3(s.background);
  }
  return s;
}

}  // namespace weft
