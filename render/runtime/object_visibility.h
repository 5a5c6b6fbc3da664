#pragma once
// The per-vertex visibility a bundle carries for one occluded object (seed 000 §3.2): the SDF
// d(θ, φ) of every vertex, PCA-compressed offline (render/bake/visibility/visibility_pca.h).
#include <cstddef>
#include <vector>

namespace weft {

// One object's visibility: d_v = mean + basis · c_v on a resolution² grid over (θ, φ) of
// the vertex's thread-1 frame (render/bake/visibility/visibility.md). The runtime reconstructs d and ∇d
// from it per (vertex, SG): methods/sg_visibility.h.
struct ObjectVisibility {
  int resolution = 0;                // cells = resolution², row-major [θ][φ]
  int terms = 0;
  std::vector<float> mean;           // [cells]
  std::vector<float> basis;          // [terms][cells]
  std::vector<float> coefficients;   // [vertices][terms]
  size_t vertex_count() const { return terms ? coefficients.size() / terms : 0; }
  double rms_error = 0, max_error = 0;  // of the PCA reconstruction (radians)
};

}  // namespace weft
