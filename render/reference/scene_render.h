#pragma once
// Ground truth of docs/design.md §2 for a whole scene: per pixel, one primary ray through the pixel
// centre (Embree); at a cloth hit the shading frame is the interpolated normal and warp, and
//   L_o = ∫ L(ω_i) V(ω_i) · ClothBsdf::Point::integrand(ω_i, ω_o) dω_i
// is integrated deterministically with visibility by shadow rays; Lambertian surfaces
// integrate albedo/π · n·ω_i instead. Direct illumination only. Two lightings:
//  - SG: the SG-warped midpoint grid of sg_quadrature.h at a fixed level (`sg_grid`);
//  - directional samples (an environment map's texels, stratified by the caller): a sum.
// Convergence is measured by re-rendering a subset of pixels at twice the resolution.
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "core/weave_layout.h"
#include "image/image.h"
#include "reference/ray_scene.h"
#include "scene/scene.h"

namespace weft {

// One direction of a discretised environment: radiance integrated over its solid-angle cell.
struct DirectionalSample {
  glm::dvec3 direction;  // unit
  glm::dvec3 power;      // ∫_cell L dω  (RGB)
};

// The lighting the reference integrates, at a given resolution level (level 0 = base; each
// level doubles the angular resolution in both directions, i.e. 4× the lighting samples, and
// doubles the tangent samples N_j).
struct ReferenceLighting {
  // SG lighting (used when non-empty).
  SgLighting sgs;
  // Otherwise: the directional samples at a level.
  std::function<std::vector<DirectionalSample>(int level)> samples;
  // Radiance seen directly along a ray (background pixels).
  std::function<glm::dvec3(const glm::dvec3&)> background;
  std::string description;
};

struct ReferenceRenderOptions {
  int width = 320, height = 240;
  int sg_grid = 8;           // SG lighting: sg_grid × 2·sg_grid cells per SG at level 0
  int tangent_samples = 32;  // N_j per thread at level 0 (each level doubles it too); docs/design.md §2: ≥ 32
  // Convergence check: every `check_stride`-th pixel (in both x and y) re-rendered at level+1.
  int check_stride = 4;
  bool check_convergence = true;
  // Cloth as an optically thin layer (methods/thin/thin.h, parameters thin_params(fabric)):
  // L = (1 − α)·reflection + single scattering (reference/thin_quadrature.h on the SG grid,
  // with visibility from either side) + α·(what the ray continues to), α = e^{−τ/|n·ω_o|}.
  // SG lighting only. Shadow rays still treat cloth as opaque.
  bool thin_cloth = false;
  // Shadow rays against the scene; false: only the surface's own horizon (its geometric normal)
  // cuts the light, for studies that split an error into shading and visibility.
  bool occlusion = true;
  // The resolved weave (docs/design.md §2): each cloth point shows the one thread sample that
  // lies there in the weave's repeat (core/weave_layout.h, sized by scene/weave_scale.h), gaps
  // black, instead of the fabric-level average. Opaque cloth only.
  bool resolved_weave = false;
  // Rays per pixel along each axis (supersample² in all, on a regular grid, averaged): what a
  // resolved close-up needs to be ground truth for a pixel that covers part of a repeat.
  int supersample = 1;
  // Called with the fraction done, from one thread, at most a few hundred times.
  std::function<void(double)> progress;
};

// Which surface a pixel sees.
enum class PixelKind : uint8_t { background = 0, cloth = 1, lambertian = 2 };

struct ConvergenceReport {
  int level = 0;                 // rendered level; compared with level+1
  size_t pixels_checked = 0;     // surface pixels of the subset
  double relative_rmse = 0.0;    // sqrt(mean |x−x₂|²)/mean |x₂| over those pixels (luminance-free RGB norm)
  double cloth_relative_rmse = 0.0;
  double max_pixel_change = 0.0; // max |x−x₂|/max(|x₂|, mean |x₂|)
  double seconds = 0.0;
};

struct ReferenceRenderResult {
  Image image;
  std::vector<PixelKind> kinds;  // per pixel
  double seconds = 0.0;
  ConvergenceReport convergence;
};

// sqrt(mean |x−x₂|²) / mean |x₂| over paired pixels (Euclidean RGB norms): how far `coarse`
// is from `fine`; 0 when `fine` is empty or black.
double relative_change(std::span<const glm::dvec3> coarse, std::span<const glm::dvec3> fine);

class ReferenceRenderer {
public:
  // `fabrics`: preset name → fabric for every cloth object of the scene.
  ReferenceRenderer(const Scene& scene, const std::map<std::string, Fabric>& fabrics, ReferenceLighting lighting,
                    const ReferenceRenderOptions& options);

  // Radiance of pixel (x, y) at a resolution level, and what it saw.
  glm::dvec3 pixel(int x, int y, int level, PixelKind* kind = nullptr) const;
  // What pixel (x, y) sees, without shading it.
  PixelKind kind(int x, int y) const;
  ReferenceRenderResult render(int level = 0) const;
  // The check subset's lattice: every check_stride-th pixel in x and y (all kinds).
  std::vector<std::pair<int, int>> check_pixels() const;
  // Re-renders the check subset at level+1 and compares it with `result` (rendered at level).
  ConvergenceReport convergence(const ReferenceRenderResult& result, int level) const;

  // Shading of a surface point seen from direction wo (unit, toward the viewer) at a level.
  glm::dvec3 shade(const RayHit& hit, const glm::dvec3& wo, int level) const;
  // A thin cloth hit seen along `dir` (options.thin_cloth), `depth` layers deep.
  glm::dvec3 shade_thin(const RayHit& hit, const glm::dvec3& dir, int level, int depth) const;

private:
  const Scene& scene_;
  RayScene rays_;
  static constexpr int kLevels = 3;
  // [level][object]; null for Lambertian.
  std::array<std::vector<std::unique_ptr<ClothBsdf>>, kLevels> bsdfs_;
  ReferenceLighting lighting_;
  ReferenceRenderOptions options_;
  struct Weave {
    WeaveLayout layout;
    std::vector<glm::dvec2> st;  // each vertex's weave coordinates (scene/weave_scale.h)
  };
  std::vector<std::optional<Weave>> weaves_;  // per object; set for cloth when resolved_weave
  mutable std::map<int, std::vector<DirectionalSample>> samples_;  // filled before parallel use
  const std::vector<DirectionalSample>& samples_at(int level) const;
  // The primary ray through pixel (x, y)'s centre (`dir`) and what it hits; its kind.
  std::optional<RayHit> primary_hit(int x, int y, glm::dvec3& dir) const;
  std::optional<RayHit> primary_hit_at(double px, double py, glm::dvec3& dir) const;
  // Radiance along the primary ray through image point (px, py).
  glm::dvec3 trace(double px, double py, int level, PixelKind* kind) const;
  PixelKind kind_of(const std::optional<RayHit>& hit) const;
};

}  // namespace weft
