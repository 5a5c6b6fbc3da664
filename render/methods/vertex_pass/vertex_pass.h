#pragma once
// Per-vertex work as a fragment pass: one texel per mesh vertex i, at (i mod W, i div W), with
// the vertex's position, normal and warp in three float textures and the result in a float
// target the mesh's vertex shader then reads by gl_VertexID. A pass may write several values per
// vertex: block b of `rows` rows holds value b, at (i mod W, i div W + b·rows). Same values as evaluating in the
// vertex stage, but llvmpipe shades vertices on one thread and fragments on all of them, and a
// GPU shades each vertex once instead of once per cached batch.
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "gl/gl_program.h"
#include "gl/gl_texture.h"
#include "gl/offscreen_target.h"
#include "scene/mesh.h"
#include "scene/vertex_pass_mesh.h"

namespace weft::gpu {

class VertexPass {
public:
  explicit VertexPass(const TriangleMesh& mesh);
  // Over a subset of the mesh's vertices (scene/vertex_pass_mesh.h; whole: every vertex): the
  // programs shade the pass vertices, and after each run every mesh vertex's value is blended
  // from its three (vertex_pass_blend.frag) into the layout above, which is what the draws read.
  // Such a pass keeps no history and shades every pass vertex (a hidden one may serve a visible
  // mesh vertex): set_history is ignored, and set_marks limits only the blend to the mesh vertices
  // the view shows.
  VertexPass(const TriangleMesh& mesh, const VertexPassMesh& pass);
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
  // The same with a rate per block: block b recomputes 1/block_shares[b] of the vertices per call
  // (a value smooth in the view, such as a broad lobe's, kept longer than a sharp one's).
  void run_shares(const GlProgram& program, int first_unit, std::span<const int> block_shares);
  // The same with a program per block (block_programs[b] draws block b, each program set up by
  // the caller): where one program would hold every block's code, a GPU runs even its cheap
  // blocks at the occupancy of its costliest (the broad lobes' quadrature beside iwasaki's SGs).
  void run_shares(std::span<const GlProgram* const> block_programs, int first_unit, std::span<const int> block_shares);
  // The kept values are stale for the next run_share (the fabric, the lighting or the eye jumped).
  void invalidate() { valid_blocks_ = 0; }
  // Extrapolated reuse: the kept values follow a moving camera. The programs write the time of
  // their run (u_pass_time, set here: seconds since an epoch of the pass's own) in each texel's
  // fourth channel, which their draw must not need (iwasaki's per-SG blocks hold RGB), and a
  // second target keeps each texel's value from its computation before the last. A draw then
  // extrapolates a kept value along the line through its last two computations to the time of the
  // frame (vertex_history.glsl), where both are of its share's latest turns since the last whole
  // pass. Off by default.
  void set_history(bool on);
  // The caller's time of the next run and of the draws after it, in seconds (any origin,
  // non-decreasing: a step back starts a new epoch, as does an hour's run, with a whole pass).
  void set_clock(double seconds) { clock_ = seconds; }
  // For a draw reading the results: u_vertex_history on `unit` (the results again without history),
  // u_history_now, u_history_floor and u_history_gap[block] (0: no extrapolation in that block).
  void bind_history(const GlProgram& program, int unit) const;
  // Visible vertices only (visible_vertices.h): from the next run on, a vertex whose mark in
  // `marks` (a buffer of one uint per vertex) is not `stamp` keeps its value, as no visible triangle
  // uses it; a share recomputes its visible vertices, and every vertex that was not visible at
  // the run before, so no kept value shown is older than a whole round of shares. Called before
  // each run with the marks for the view it draws.
  void set_marks(GLuint marks, unsigned stamp);
  // Every vertex again; the values kept while marked may be of any age, so the next run is whole.
  void clear_marks() {
    if (marked_) valid_blocks_ = 0;
    marked_ = false;
    blend_marked_ = false;
  }
  // The results for the mesh's draw: u_vertex_radiance on `unit`, u_vertex_width, u_vertex_rows.
  void bind_result(const GlProgram& program, int unit) const;
  // The results' texture, for a program that reads them under its own name (no results yet: 0).
  GLuint result_texture() const {
    const OffscreenTarget* r = results();
    return r ? r->colour_texture() : 0;
  }
  int texels() const { return mesh_width_ * mesh_height_; }  // of a block of the results (per mesh vertex)
  int width() const { return mesh_width_; }  // texels a row: mesh vertex i at (i mod width, i div width)
  int pass_vertices() const { return count_; }
  // The results' texels (RGBA float, row-major, blocks one above the other), for tests.
  std::vector<float> read_values() const { return results() ? results()->read_rgba() : std::vector<float>{}; }

private:
  int count_, width_, height_;  // the pass vertices' layout; height_: rows per block
  int mesh_count_, mesh_width_, mesh_height_;  // the mesh's (the same where every vertex is a pass vertex)
  bool subset_ = false;
  GlTexture blend_corners_, blend_weights_;  // per mesh vertex, where subset_
  std::unique_ptr<OffscreenTarget> blended_;
  int blended_blocks_ = 0;
  bool blend_marked_ = false;  // set_marks on a subset: the blend only for the marked mesh vertices
  unsigned blend_stamp_ = 0;
  std::unique_ptr<GlProgram> blend_;
  const OffscreenTarget* results() const { return subset_ ? blended_.get() : target_.get(); }
  void blend(int blocks);  // the mesh vertices' values from the pass's, every block
  void run_blocks(std::span<const GlProgram* const> block_programs, int first_unit, std::span<const int> block_shares);
  GlTexture position_, normal_, warp_;
  std::unique_ptr<OffscreenTarget> target_;
  int target_blocks_ = 0;
  int valid_blocks_ = 0;  // blocks holding values from a whole pass (0: none)
  long calls_ = 0;
  // The marks of this run and of the run before (R32UI, a texel per vertex as the inputs).
  GlTexture marks_[2];
  int current_marks_ = 0;  // marks_[current_marks_]: this run's
  unsigned stamp_ = 0, previous_stamp_ = 0;
  bool marked_ = false;  // run_shares calls since the last whole pass: block b draws share calls_ mod its shares
  // History (set_history): each texel's value before its last computation; the clock.
  bool history_ = false;
  std::unique_ptr<OffscreenTarget> previous_;
  double clock_ = 0.0, epoch_ = 0.0;
  bool epoch_set_ = false;
  float now_ = 0.0f, floor_ = 0.0f;  // the run's time and the last whole pass's, since the epoch
  std::vector<float> run_times_;     // since the last whole pass, oldest first
  std::vector<float> gaps_;          // per block: the longest chord still of its share's turns
  void start_run();                  // the clock's time for this run (a new epoch: a whole pass)
  void clear_history();              // every history texel before any floor (previous_ exists)
  void copy_to_history(const std::vector<std::pair<int, int>>& ranges);  // each block's range, before it is recomputed
  // Block b recomputes vertices [ranges[b].first, ranges[b].second).
  // Each distinct program draws its own blocks (rows of the target), in turn.
  void draw_blocks(std::span<const GlProgram* const> programs, int first_unit, const std::vector<std::pair<int, int>>& ranges);
  // One program's blocks (mine[b]): all at once where it draws them all, else each run of them.
  void draw_program_blocks(const GlProgram& program, int first_unit, const std::vector<std::pair<int, int>>& ranges,
                           const std::vector<bool>& mine, bool whole);
};

}  // namespace weft::gpu
