#pragma once
// The per-vertex passes' texel layout (methods/vertex_pass/vertex_pass.h): vertex i is the texel
// (i mod W, i div W) with W = min(vertex count, kVertexTexelRow). Shared by the passes and by
// the bake's vertex order (scene/mesh_vertex_order.h), which places nearby vertices in one
// rasteriser block.
namespace weft {

inline constexpr int kVertexTexelRow = 256;  // texels per row: small rows keep the target near square
inline constexpr int kVertexTexelBlock = 4;  // llvmpipe shades fragments in 4×4 blocks

}  // namespace weft
