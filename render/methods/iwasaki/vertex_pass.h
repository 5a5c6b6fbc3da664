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
  // Temporal reuse: the same pass over one share of the vertices, the next share each call, so
  // every vertex is recomputed once every `shares` calls and the others keep their last values
  // (a slowly moving camera changes them little; methods/cloth_method.h's set_vertex_refresh). The
  // whole pass runs instead when nothing valid is kept: the first run, a larger target, a run
  // with other blocks, or after invalidate(). shares ≤ 1: run().
  void run_share(const GlProgram& program, int first_unit, int blocks, int shares);
  // The kept values are stale for the next run_share (the fabric, the lighting or the eye jumped).
  void invalidate() { valid_blocks_ = 0; }
  // The results for the mesh's draw: u_vertex_radiance on `unit`, u_vertex_width, u_vertex_rows.
  void bind_result(const GlProgram& program, int unit) const;

private:
  int count_, width_, height_;  // height_: rows per block
  GlTexture position_, normal_, warp_;
  std::unique_ptr<OffscreenTarget> target_;
  int target_blocks_ = 0;
  int valid_blocks_ = 0;  // blocks holding values from a whole pass (0: none)
  int next_share_ = 0;
  void draw_blocks(const GlProgram& program, int first_unit, int blocks, int begin, int end);
};

}  // namespace weft::gpu
