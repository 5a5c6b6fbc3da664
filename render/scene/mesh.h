#pragma once
// A triangle mesh as scenes hold it: positions, per-vertex normals and UVs, and for cloth the
// warp direction field derived from the UVs (docs/design.md §2: thread 1 runs along u).
#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace weft {

struct VertexPassMesh;  // scene/vertex_pass_mesh.h

struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // per vertex, unit; filled by finish_mesh when empty
  std::vector<glm::dvec2> uvs;      // per vertex; required for cloth
  std::vector<glm::dvec3> warps;    // per vertex, unit, ⟂ normal; filled by finish_mesh
  std::vector<std::array<uint32_t, 3>> triangles;
  // The vertices the per-vertex passes shade, where the mesh is denser than its shading needs
  // (vertex_pass_mesh.h); set on the finished mesh by its loader, null: every vertex.
  std::shared_ptr<const VertexPassMesh> pass;
};

// A mesh that cannot be used; what() names the mesh and the problem.
class MeshError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct MeshRepairReport {
  size_t degenerate_triangles_dropped = 0;  // repeated indices or (near) zero area
  size_t unused_vertices = 0;               // kept, but not referenced by any triangle
};

// Validates and repairs a mesh in place:
//  - rejects (MeshError) non-finite positions/UVs/normals, out-of-range indices, attribute
//    arrays whose length differs from positions, a cloth mesh without UVs, an empty result;
//  - drops degenerate triangles (area below 1e-12 of the bounding box diagonal squared) and
//    triangles whose UV parallelogram is degenerate on cloth (no warp direction there).
// `name` appears in errors.
MeshRepairReport repair_mesh(TriangleMesh& mesh, bool needs_uvs, const std::string& name);

// Area-weighted vertex normals (consistently oriented input assumed).
void compute_vertex_normals(TriangleMesh& mesh);
// A unit tangent ⟂ unit normal n from direction w: w's part across n, normalised, projected once
// more (the first pass's rounding). Where w lies along n (within 1e−6 of its length, too few digits
// left for a frame) or is zero, a fixed one: (1,0,0) × n, or (0,1,0) × n near ±x.
glm::dvec3 unit_tangent(const glm::dvec3& w, const glm::dvec3& n);
// Warp field: per triangle dP/du from its UVs, accumulated per vertex by area, then
// orthogonalised against the vertex normal (Gram–Schmidt) and normalised. Requires normals; a
// mesh without UVs (occluders, floors) gets a fixed tangent, (1,0,0) × n (or (0,1,0) × n near ±x):
// it only has to give every vertex a frame, which the visibility bake and its lookup share.
void compute_warp_directions(TriangleMesh& mesh);

// repair_mesh, then normals (if absent) and warps. Returns the repair report.
MeshRepairReport finish_mesh(TriangleMesh& mesh, bool is_cloth, const std::string& name);

// Merges vertices closer than `tolerance` (and, when UVs exist, with equal UVs), remapping
// triangles: patch-built meshes then get smooth normals across patch seams.
void weld_vertices(TriangleMesh& mesh, double tolerance);

}  // namespace weft
