#pragma once
// Per-vertex work as a fragment pass: one texel per mesh vertex i, at (i mod W, i div W), with
// the vertex's position, normal and warp in three float textures and the result in a float
// target the mesh's vertex shader then reads by gl_VertexID. A pass may write several values per
// vertex: block b of `rows` rows holds value b, at (i mod W, i div W + b·rows). Same values as evaluating in the
// vertex stage, but llvmpipe shades vertices on one thread and fragments on all of them, and a
// GPU shades each vertex once instead of once per cached batch.
#include <memory>

#include "gl/gl_program.h"
#include "methods/iwasaki/iwasaki_textures.h"
#include "gl/offscreen_target.h"
#include "scene/mesh.h"

namespace weft::gpu {

class VertexPass {
public:
  explicit VertexPass(const TriangleMesh& mesh);
  // Draws `program` (in use; built on fullscreen_triangle_vs()) over `blocks` blocks of the vertex
  // texels with the inputs on units first_unit .. first_unit + 2 (u_vertex_position,
  // u_vertex_normal, u_vertex_warp, plus u_vertex_width, u_vertex_rows and u_vertex_count). The
  // caller's framebuffer, viewport, depth test and blending are restored afterwards. Throws
  // GpuError where the blocks do not fit the GL's largest texture.
  void run(const GlProgram& program, int first_unit, int blocks = 1);
  // The results for the mesh's draw: u_vertex_radiance on `unit`, u_vertex_width, u_vertex_rows.
  void bind_result(const GlProgram& program, int unit) const;

private:
  int count_, width_, height_;  // height_: rows per block
  GlTexture position_, normal_, warp_;
  std::unique_ptr<OffscreenTarget> target_;
  int target_blocks_ = 0;
};

}  // namespace weft::gpu
