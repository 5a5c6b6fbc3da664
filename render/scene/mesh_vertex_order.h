#pragma once
// A spatial order of a mesh's vertices for the kiosk's per-vertex passes. Those shade vertex i
// at texel (i mod W, i div W) (scene/vertex_texels.h) and only the vertices a visible triangle
// uses; llvmpipe shades fragments in 4×4 blocks, and a block with one visible vertex costs what
// a block of sixteen does. A glTF's vertex order is its tool's, so a view's visible vertices are
// scattered over most blocks. The bake groups the vertices by facing (the nearest of 14
// directions: a thin part's two sides are close in space but not seen together), orders each
// group along a Morton curve (meshoptimizer's spatial sort) and lays the result out block by
// block, so each 4×4 block holds 16 consecutive vertices: a small patch of the surface facing
// one way, visible or hidden together. Everything baked per vertex after the order (visibility,
// masks) follows it.
//
// In weft_scene_files (it links meshoptimizer): the bake's, not the kiosk's.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene/vertex_texels.h"

namespace weft {

// new_index[old] for the mesh's vertices: the order above along the 4×4 blocks of a texel grid
// `row` texels wide (min(row, count) when fewer), block row by block row, each block row-major
// within; a permutation of 0 .. count−1. Without a normal per vertex, one group.
std::vector<uint32_t> spatial_vertex_order(const TriangleMesh& mesh, int row = kVertexTexelRow);

// Moves vertex v to new_index[v] in every per-vertex array that is not empty and renumbers the
// triangles (their order and winding kept). new_index must be a permutation of the vertices.
void permute_vertices(TriangleMesh& mesh, std::span<const uint32_t> new_index);

// permute_vertices(mesh, spatial_vertex_order(mesh)).
void order_vertices_spatially(TriangleMesh& mesh);

// Every object's mesh ordered (cloth, floors and occluders alike): what the bake stores.
Scene order_scene_meshes(Scene scene);

// The bake's meshes at `levels` of refinement of a scene it has ordered: the cloth meshes refined
// (scene/mesh_subdivision.h), which appends the edge midpoints out of order, then ordered anew
// (floors and occluders as given); levels 0: the scene as given. Ordering an ordered mesh again
// may swap vertices whose Morton cells tie, so whatever is baked for a density and whatever draws
// it both take their meshes from here.
Scene refine_and_order_meshes(Scene scene, int levels);

}  // namespace weft
