#pragma once
// Which vertices are one: those whose positions (and UVs, where given) round to the same point of
// a grid. weld_vertices merges them; mesh_orientation reads a closed surface through them.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace weft {

// Each vertex's id, numbered in order of first appearance: equal for vertices whose
// (position − origin) / step rounds to the same integers and, when `uvs` is not empty (one per
// vertex), whose uv / step does too.
std::vector<uint32_t> welded_ids(std::span<const glm::dvec3> positions, double step, const glm::dvec3& origin = glm::dvec3(0.0),
                                 std::span<const glm::dvec2> uvs = {});

}  // namespace weft
