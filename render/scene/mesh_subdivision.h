#pragma once
// Midpoint (1→4) refinement of a triangle mesh: every edge gets one new vertex at its midpoint
// (an edge two triangles share, by vertex indices, is split once, so an indexed mesh stays
// indexed and without cracks), every triangle becomes four. Positions and UVs are linear on
// the triangle, so the surface, its area and its UV map are unchanged; the new vertex's normal
// is the normalised mean of its edge's two, and its warp the mean of theirs made ⟂ that normal
// and normalised: the values the reference renderer interpolates at that point
// (reference/ray_scene.cpp). What it buys: a per-vertex method (iwasaki_vertex) shades at four
// times the vertices per level, and its Gouraud interpolation spans a quarter of the area.
//
// Written here rather than with a halfedge library (OpenMesh, CGAL: both in Debian): their
// uniform subdividers move positions by their own rules and carry none of these attributes,
// and they refuse the non-manifold edges a glTF may hold; a split over an edge map is short.
#include "scene/mesh.h"
#include "scene/scene.h"

namespace weft {

// One level: vertices V + E (E = distinct edges; the first V keep their index and values),
// triangles 4T, each in the winding of its parent. Attribute arrays that are empty stay empty.
TriangleMesh subdivide_midpoint(const TriangleMesh& mesh);
// `levels` ≥ 0 levels (0: a copy).
TriangleMesh subdivide_midpoint(const TriangleMesh& mesh, int levels);

// The scene with every cloth object's mesh refined `levels` times (floors and occluders are
// shaded per vertex only by their irradiance, which varies slowly: they keep their meshes).
Scene refine_cloth_meshes(Scene scene, int levels);

}  // namespace weft
