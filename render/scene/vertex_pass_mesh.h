#pragma once
// The vertices a per-vertex pass shades (methods/vertex_pass/vertex_pass.h), for a mesh denser than its
// shading needs. A product export carries the density its modelling tool left (a 100k-vertex
// sofa whose panels are nearly flat); the per-vertex rungs and the weave layer's vertex level only
// need enough vertices for their interpolated shading to follow the surface. The pass mesh keeps a
// subset of the mesh's own vertices (meshoptimizer's simplifier: every kept vertex is a vertex of
// the mesh, with its position, normal and warp, so what is baked per vertex stays exact there) and
// gives every mesh vertex three of them and weights: the draw reads each vertex's value blended
// from those, as the rasteriser blends a coarse triangle's corners. The full mesh is still what is
// drawn: its silhouette and per-pixel terms are untouched.
//
// How coarse: the coarsest of a ladder of the simplifier's geometric errors whose blended normals
// and warps stay within an angle budget at the mesh's vertices (the shading's inputs: a per-vertex
// value is a function of them), and whose edges stay within a length (the screen's: the kiosk's
// view of the object at its closest zoom), every vertex near its blend point. A border vertex (the cloth's
// outline) moves only along the border. Meshes up to kKeepAllVertices keep every vertex.
//
// In weft_scene_files (it links meshoptimizer).
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"
#include "scene/scene.h"

namespace weft {

struct VertexPassMesh {
  // The pass's vertices: indices into the mesh's, ascending (the bake's spatial order kept). Empty:
  // every vertex of the mesh, each its own (no blending).
  std::vector<uint32_t> vertices;
  // Per mesh vertex: three pass vertices (indices into `vertices`) and their weights (sum 1).
  std::vector<std::array<uint32_t, 3>> corners;
  std::vector<glm::vec3> weights;
  bool whole() const { return vertices.empty(); }
  // Measured on the mesh's vertices: blended against own, degrees (95th percentile, largest).
  double normal_p95_deg = 0, normal_p99_deg = 0, normal_max_deg = 0, warp_p95_deg = 0, warp_max_deg = 0;
  double edge_p95 = 0, edge_median = 0;  // the pass triangles' edges, metres
  double gap_max = 0;         // the farthest a mesh vertex lies from its blend point, metres
  double gap_p999 = 0;        // and the 99.9th percentile of that distance
  float simplifier_error = 0;  // the ladder's step taken (relative to the mesh's extent)
  // Whole although the mesh is large enough for a subset: what the finest step measured against
  // the budget (for the bake's log); empty otherwise.
  std::string kept_whole_because;
};

struct VertexPassMeshOptions {
  static constexpr size_t kKeepAllVertices = 4096;  // below: the pass costs less than blending it
  size_t keep_all_below = kKeepAllVertices;
  double normal_p95_deg = 4.0;  // the budget: 95 % of the mesh's vertices within these
  double warp_p95_deg = 8.0;
  double normal_p99_deg = 15.0;  // and 99 %: creases and seams stay on their own side
  // Metres: the simplifier is steered to triangles near this edge (a ripple of twice it along the
  // normals, vertex_pass_mesh.cpp), and a step whose edges exceed 1.5 times it at the 95th
  // percentile is refused. Infinite: no bound.
  double max_edge = std::numeric_limits<double>::infinity();
};

// The pass mesh for `mesh` (normals and warps per vertex, as finish_mesh leaves them). Whole where
// the mesh is small or no step of the ladder keeps the budget.
VertexPassMesh vertex_pass_mesh(const TriangleMesh& mesh, const VertexPassMeshOptions& options = {});

// The pass mesh `mesh` carries where it fits the mesh (a corner per vertex), else whole: what a
// per-vertex pass shades. Inline: the kiosk's passes read it without the simplifier's library.
inline const VertexPassMesh& pass_of(const TriangleMesh& mesh) {
  static const VertexPassMesh whole;
  return mesh.pass && mesh.pass->corners.size() == mesh.positions.size() ? *mesh.pass : whole;
}

// Every cloth object's pass mesh (TriangleMesh::pass), its edges bounded by the nearest view the
// scene's cameras (its camera, its close-up) have of the object: an edge subtends at most
// kPassEdgeDegrees there. WEFT_PASS_MESH=whole in the environment: none (every vertex), to compare.
inline constexpr double kPassEdgeDegrees = 3.0;
// Returns pass_mesh_report(scene, report_prefix).
std::string set_pass_meshes(Scene& scene, const std::string& report_prefix = "");

// A line per object whose passes shade a subset ("<prefix><object>: per-vertex passes on N of M
// vertices (…)"), for the bake's and the renderer's logs; empty when none does.
std::string pass_mesh_report(const Scene& scene, const std::string& prefix);

// Per mesh vertex: the three corners' values blended by the weights (whole: `pass_values` itself),
// for values given per pass vertex. What the GPU's expansion does; for tests and CPU twins.
std::vector<glm::dvec3> blend_pass_values(const VertexPassMesh& pass, const std::vector<glm::dvec3>& pass_values);

}  // namespace weft
