#pragma once
// Where the weave layer can show anything. Each vertex's thread footprint (threads a pixel, as
// weave_layer.frag measures it: the longer of a pixel's two steps in tile space, times the rows)
// from the eye: for each of its triangles, the ray differentials of a one-pixel step carried onto
// the triangle's plane and mapped by its tile-coordinate gradient, scaled for the nearest point
// the triangle can bring (the distance less its longest edge); the smallest of them. Where no
// vertex in view comes under kWeaveCoarseFootprint the layer draws nothing, so nothing is
// computed (WeaveLayer::resolves), and the vertex passes skip each vertex at or above it
// (weave_reach.glsl). A bound for any view direction (the UV map's largest stretch alone, over √2:
// a pixel's footprint on the surface has both sides at least a pixel's) prunes clusters of
// vertices, and lets the kiosk skip an object's lights when no camera of its zoom range can come
// under it (nearest_footprint_orbiting).
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"
#include "scene/scene.h"

namespace weft {

// A view as the reach needs it: the frustum's side planes, the eye and its axes, the side of a
// pixel at unit depth, and the smallest side of one at unit distance (at the image's corners, where
// a pixel's ray is longest: pixel·cos² of the half diagonal) (a `width` × `height` image of `camera`).
struct WeaveView {
  glm::dmat4 view_projection{1.0};
  glm::dvec3 eye{0.0}, forward{0.0, 0.0, -1.0}, right{1.0, 0.0, 0.0}, up{0.0, 1.0, 0.0};
  double pixel = 0.0, corner_pixel = 0.0;
};
WeaveView weave_view(const Camera& camera, int width, int height);

class WeaveReach {
public:
  struct Vertex {
    float radius = 0.0f;  // metres: its longest edge
    // The smallest footprint any view direction can give per metre of depth: the rows × the
    // smallest over its triangles of their largest tile stretch, over √2 (0 where a triangle's
    // UVs collapse to a point: the layer draws its finest there); infinity in no triangle.
    float threads_per_metre = std::numeric_limits<float>::infinity();
  };
  // `st`: each vertex's weave coordinates (scene/weave_scale.h's weave_coordinates), of a weave
  // of `rows` threads across a repeat.
  WeaveReach(const TriangleMesh& mesh, std::span<const glm::dvec2> st, int rows);
  const std::vector<Vertex>& vertices() const { return vertices_; }
  // Vertex i's footprint from `view` (infinity where it is seen edge-on or from behind the eye).
  double vertex_footprint(size_t i, const WeaveView& view) const;
  // The smallest footprint of any vertex within the view's frustum (infinity where none is):
  // footprints with no limit.
  double nearest_footprint(const WeaveView& view) const;
  // Every vertex's footprint into `out` (one a vertex), where it may come under `limit`; 1e30
  // where it cannot (out of the frustum, or its cluster's bound for any direction at or above
  // `limit`). Returns the smallest.
  double footprints(const WeaveView& view, double limit, std::vector<float>& out) const;
  // The smallest footprint from any eye on the circle `eye` sweeps turning about the vertical
  // through `pivot` (the kiosk's turntable), whatever it looks at (WeaveView::corner_pixel `pixel`).
  double nearest_footprint_orbiting(const glm::dvec3& eye, const glm::dvec3& pivot, double pixel) const;

private:
  struct Cluster {  // consecutive vertices, bounded by a sphere
    glm::dvec3 centre{0.0};
    double radius = 0.0;             // the sphere's, plus its vertices' reach
    double threads_per_metre = 0.0;  // the smallest of its vertices'
    size_t begin = 0, end = 0;
  };
  struct Triangle {
    glm::dvec3 ds{0.0}, dt{0.0};  // ∂s/∂P and ∂t/∂P times the rows: threads per metre
    glm::dvec3 normal{0.0};       // unit
    double longest = 0.0;         // its longest edge
  };
  std::vector<glm::dvec3> positions_;
  std::vector<Vertex> vertices_;
  std::vector<Triangle> triangles_;                    // those with area
  std::vector<uint32_t> first_triangle_, triangle_of_;  // vertex i's: triangle_of_[first_[i] … first_[i + 1])
  std::vector<Cluster> clusters_;
};

}  // namespace weft
