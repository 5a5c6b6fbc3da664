#pragma once
// The visibility bake (seed 000 §3.2) for a whole scene: for every vertex of an object (cloth, floor,
// occluder), binary
// visibility over its hemisphere by ray casting against the scene (Embree), the signed distance
// function d(θ, φ) (visibility_sdf.h), and PCA over the object's vertices (visibility_pca.h).
// An object none of whose rays is blocked by anything stores nothing: it is unoccluded.
#include <functional>
#include <optional>

#include "runtime/shading_data.h"
#include "bake/visibility/visibility_pca.h"
#include "scene/scene.h"

namespace weft {

struct SceneVisibilityOptions {
  // The paper's 128² (it samples 512² and keeps 128²). The runtime never expands the grids: it
  // reconstructs d only at the SG axes when the lighting changes (methods/sg_visibility.h),
  // so the resolution costs bundle bytes (the PCA basis) and bake time, not GPU memory.
  // Measured, pillow/linen/studio, iwasaki vs reference: 32² 29.0 %, 64² 24.1 %, 128² 20.7 %.
  int resolution = 128;
  // Floors and occluders (Lambertian, methods/lambert_visibility.h) bake at min(resolution, this):
  // the cosine-weighted lobes they are shaded with are broad. Against ray-cast quadrature
  // (tests/methods/lambert_visibility_test.cpp) 32² 1.9 %, 64² 2.0 %, 128² 2.25 % relative RMSE, while
  // the basis costs 4× the bytes per doubling (the pillow's floor: 5.3 MB at 128²).
  int lambertian_resolution = 64;
  int supersample = 1;
  SdfPcaOptions pca;
};

struct SceneVisibilityStats {
  size_t vertices = 0;
  double blocked_share = 0;  // share of cast rays (above the horizon) that hit something
  double seconds = 0;
};

// Bakes object `object` (any mesh with warps: finish_mesh gives every mesh its frames). Empty when no ray is blocked.
// `progress(done, total)` counts vertices.
std::optional<ObjectVisibility> bake_object_visibility(const Scene& scene, size_t object,
                                                       const SceneVisibilityOptions& options,
                                                       const std::function<void(size_t, size_t)>& progress = {},
                                                       SceneVisibilityStats* stats = nullptr);

}  // namespace weft
