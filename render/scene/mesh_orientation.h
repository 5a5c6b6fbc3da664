#pragma once
// A closed part's outside from its own shape. Product files arrive with a part's normals (and
// often its winding) pointing into it — a modelling tool's "recalculate outside" missed, a
// mirrored export — and a renderer that draws both sides hides it, but Weft's visibility bake
// casts its rays along the normals: every ray from inside a closed part is blocked, and the kiosk
// draws the part black. Only a closed mesh has an inside, so only a closed one is turned.
#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "scene/mesh.h"

namespace weft {

struct MeshOrientation {
  bool closed = false;          // every edge (vertices welded by position) shared by two triangles, oppositely wound
  bool winding_inward = false;  // its triangles' winding encloses a negative volume
  bool normals_inward = false;  // its vertex normals point against the outward faces, on the whole
  bool inward() const { return winding_inward || normals_inward; }
};

// What `mesh` (positions, triangles, normals when present) shows of its orientation.
MeshOrientation mesh_orientation(const TriangleMesh& mesh);

// Turns what points in to point out: the winding (each triangle's last two corners swapped) and
// the normals (negated), as `o` says; spans, so that a part merged into a larger mesh turns in place.
void turn_outward(std::span<std::array<uint32_t, 3>> triangles, std::span<glm::dvec3> normals, const MeshOrientation& o);

}  // namespace weft
