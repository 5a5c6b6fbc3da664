#include "bench/shadow_mask.h"

#include <algorithm>
#include <stdexcept>

#include "reference/ray_scene.h"

namespace weft::bench {

ShadowMask sun_shadow_mask(const Scene& scene, const SgLighting& sgs, int width, int height, int band_px) {
  if (sgs.empty()) throw std::invalid_argument("sun_shadow_mask: no SGs");
  ShadowMask m;
  // Peak radiance, not power: a broad sky lobe can carry as much power but casts no crisp shadow.
  auto peak = [](const SphericalGaussian& g) { return g.amplitude.r + g.amplitude.g + g.amplitude.b; };
  m.sun = *std::max_element(sgs.begin(), sgs.end(), [&](const auto& a, const auto& b) { return peak(a) < peak(b); });
  const glm::dvec3 sun = glm::normalize(m.sun.axis);
  const RayScene rays(scene);
  const size_t n = size_t(width) * size_t(height);
  m.shadow.assign(n, false);
  std::vector<bool> lit(n, false);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 dir = camera_ray(scene.camera, width, height, x + 0.5, y + 0.5);
      const auto hit = rays.intersect(scene.camera.position, dir);
      if (!hit || !scene.objects[hit->object].is_cloth()) continue;
      const SurfacePoint s = rays.surface(*hit);
      // Two-sided cloth: the side the camera sees (as the reference shades it).
      const glm::dvec3 ng = glm::dot(s.geometric_normal, dir) > 0.0 ? -s.geometric_normal : s.geometric_normal;
      if (glm::dot(ng, sun) <= 0.0) continue;
      const bool blocked = !rays.unoccluded(s.position + ng * rays.ray_epsilon(), sun);
      (blocked ? m.shadow : lit)[size_t(y) * width + x] = true;
    }
  m.band.assign(n, false);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * width + x;
      if (m.shadow[i]) ++m.shadow_pixels;
      if (!lit[i]) continue;
      bool near = false;
      for (int dy = -band_px; dy <= band_px && !near; ++dy)
        for (int dx = -band_px; dx <= band_px && !near; ++dx) {
          const int xx = x + dx, yy = y + dy;
          near = xx >= 0 && yy >= 0 && xx < width && yy < height && m.shadow[size_t(yy) * width + xx];
        }
      if (near) m.band[i] = true, ++m.band_pixels;
    }
  return m;
}

}  // namespace weft::bench
