#include "methods/vertex_pass/vertex_pass.h"

#include <algorithm>
#include <string>
#include <vector>

#include <GLES3/gl31.h>

#include "gl/frame_profile.h"
#include "gl/gl_error.h"
#include "methods/program_cloth.h"
#include "scene/vertex_texels.h"

namespace weft::gpu {

namespace {
constexpr int kWidth = kVertexTexelRow;  // the bake orders vertices for this layout
constexpr int kMaxBlocks = 40;  // MAX_PASS_BLOCKS in vertex_pass.glsl
constexpr int kMarkUnit = 14;   // the marks' two samplers: above every pass's own units
constexpr int kBlendUnit = 11;  // the blend's four samplers, 11–14 (their bindings restored after)

void allocate_marks(const GlTexture& t, int width, int height) {
  std::vector<GLuint> zero(size_t(width) * height, 0u);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, width, height, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, zero.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

// Vertices [begin, end) of a block of `width`-texel rows are texels of whole rows between a partial
// first and last row: up to three rectangles (x0, x1, y0, y1), rows counted within the block.
template <class Rect>
void range_rectangles(int begin, int end, int width, Rect rect) {
  const int r0 = begin / width, c0 = begin % width, r1 = end / width, c1 = end % width;
  auto some = [&](int x0, int x1, int y0, int y1) {
    if (x1 > x0 && y1 > y0) rect(x0, x1, y0, y1);
  };
  if (r0 == r1) {
    some(c0, c1, r0, r0 + 1);
  } else {
    some(c0, width, r0, r0 + 1);
    some(0, width, r0 + 1, r1);
    some(0, c1, r1, r1 + 1);
  }
}

// The caller's framebuffer, viewport and the tests a pass turns off (depth, blending, scissor),
// taken when a pass starts (before a new target binds its own) and given back when it ends.
class CallerState {
public:
  CallerState() {
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
  }
  CallerState(const CallerState&) = delete;
  ~CallerState() {
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    for (int i = 0; i < 3; ++i) (tests_[i] ? glEnable : glDisable)(kTests[i]);
  }

private:
  static constexpr GLenum kTests[3] = {GL_DEPTH_TEST, GL_BLEND, GL_SCISSOR_TEST};
  GLint framebuffer_ = 0, viewport_[4] = {0, 0, 0, 0};
  const GLboolean tests_[3] = {glIsEnabled(kTests[0]), glIsEnabled(kTests[1]), glIsEnabled(kTests[2])};
};

// Marks (a uint per mesh vertex in the buffer `marks`, written by shaders) into the texture `t`.
void upload_marks(const GlTexture& t, GLuint marks, int width, int height) {
  glMemoryBarrier(GL_PIXEL_BUFFER_BARRIER_BIT);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, marks);
  glActiveTexture(GL_TEXTURE0 + kMarkUnit);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

// Per texel: values[i] in .xyz, fourth[i] in .w where given.
void upload(const GlTexture& t, const std::vector<glm::dvec3>& values, int width, int height,
            const std::vector<float>& fourth = {}) {
  std::vector<float> texels(size_t(width) * height * 4, 0.0f);
  for (size_t i = 0; i < values.size(); ++i) {
    for (int c = 0; c < 3; ++c) texels[i * 4 + c] = float(values[i][c]);
    if (i < fourth.size()) texels[i * 4 + 3] = fourth[i];
  }
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}
}  // namespace

VertexPass::VertexPass(const TriangleMesh& mesh) : VertexPass(mesh, VertexPassMesh{}) {}

VertexPass::VertexPass(const TriangleMesh& mesh, const VertexPassMesh& pass)
    : count_(pass.whole() ? int(mesh.positions.size()) : int(pass.vertices.size())),
      width_(std::clamp(count_, 1, kWidth)),
      height_(std::max(1, (count_ + kWidth - 1) / kWidth)),
      mesh_count_(int(mesh.positions.size())),
      mesh_width_(std::clamp(mesh_count_, 1, kWidth)),
      mesh_height_(std::max(1, (mesh_count_ + kWidth - 1) / kWidth)),
      subset_(!pass.whole()) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (mesh_height_ > max_size)
    throw GpuError("per-vertex pass: " + std::to_string(mesh_count_) + " vertices do not fit a " + std::to_string(kWidth) + "×" +
                   std::to_string(max_size) + " texture");
  if (mesh.normals.size() != mesh.positions.size() || mesh.warps.size() != mesh.positions.size())
    throw GpuError("per-vertex pass: the mesh needs a normal and a warp per vertex");
  if (subset_ && (pass.corners.size() != mesh.positions.size() || pass.weights.size() != mesh.positions.size() ||
                  std::any_of(pass.vertices.begin(), pass.vertices.end(), [&](uint32_t v) { return v >= mesh.positions.size(); })))
    throw GpuError("per-vertex pass: its pass vertices do not fit the mesh");
  // The pass vertices' inputs, each with its mesh vertex in the position's .w (exact below 2^24).
  std::vector<uint32_t> source(static_cast<size_t>(count_));
  for (int n = 0; n < count_; ++n) source[size_t(n)] = subset_ ? pass.vertices[size_t(n)] : uint32_t(n);
  std::vector<glm::dvec3> positions, normals, warps;
  std::vector<float> index;
  for (uint32_t v : source) {
    positions.push_back(mesh.positions[v]);
    normals.push_back(mesh.normals[v]);
    warps.push_back(mesh.warps[v]);
    index.push_back(float(v));
  }
  upload(position_, positions, width_, height_, index);
  upload(normal_, normals, width_, height_);
  upload(warp_, warps, width_, height_);
  for (const auto& m : marks_) allocate_marks(m, mesh_width_, mesh_height_);
  if (subset_) {
    std::vector<glm::dvec3> corners, weights;
    for (size_t v = 0; v < pass.corners.size(); ++v) {
      for (uint32_t c : pass.corners[v])
        if (c >= pass.vertices.size()) throw GpuError("per-vertex pass: a blend corner past the pass vertices");
      corners.emplace_back(pass.corners[v][0], pass.corners[v][1], pass.corners[v][2]);
      weights.emplace_back(pass.weights[v]);
    }
    upload(blend_corners_, corners, mesh_width_, mesh_height_);
    upload(blend_weights_, weights, mesh_width_, mesh_height_);
    blend_ = std::make_unique<GlProgram>(fullscreen_triangle_vs(), program_source({"vertex_pass_blend.frag"}));
  }
  check_gl("uploading the per-vertex pass inputs");
}

void VertexPass::set_marks(GLuint marks, unsigned stamp) {
  if (subset_) {  // every pass vertex (a hidden one may serve a visible mesh vertex); the blend only the shown
    blend_marked_ = true;
    blend_stamp_ = stamp;
    upload_marks(marks_[0], marks, mesh_width_, mesh_height_);
    return;
  }
  if (!marked_) valid_blocks_ = 0;  // values kept from before were not kept by marks: all visible ones anew
  current_marks_ = 1 - current_marks_;
  previous_stamp_ = stamp_;
  stamp_ = stamp;
  marked_ = true;
  upload_marks(marks_[current_marks_], marks, mesh_width_, mesh_height_);
}

void VertexPass::run(const GlProgram& program, int first_unit, int blocks) {
  run_shares(program, first_unit, std::vector<int>(size_t(std::max(blocks, 1)), 1));  // every share 1: the whole pass
}

void VertexPass::run_share(const GlProgram& program, int first_unit, int blocks, int shares) {
  run_shares(program, first_unit, std::vector<int>(size_t(std::max(blocks, 1)), shares));
}

void VertexPass::run_shares(const GlProgram& program, int first_unit, std::span<const int> block_shares) {
  const std::vector<const GlProgram*> programs(std::max<size_t>(block_shares.size(), 1), &program);
  const std::vector<int> shares = block_shares.empty() ? std::vector<int>{1} : std::vector<int>(block_shares.begin(), block_shares.end());
  run_shares(programs, first_unit, shares);
}

void VertexPass::run_shares(std::span<const GlProgram* const> block_programs, int first_unit, std::span<const int> block_shares) {
  run_blocks(block_programs, first_unit, block_shares);
  if (subset_) blend(int(block_shares.size()));
}

void VertexPass::blend(int blocks) {
  const StageScope stage(Stage::vertex_pass);
  const CallerState caller;
  GLint program = 0, active = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  bool whole = !blend_marked_;  // a new target holds nothing to keep: every vertex then
  if (blocks > blended_blocks_) {
    blended_ = std::make_unique<OffscreenTarget>(mesh_width_, mesh_height_ * blocks, /*full_float=*/true);
    blended_blocks_ = blocks;
    whole = true;
  }
  blended_->bind();
  glViewport(0, 0, mesh_width_, mesh_height_ * blocks);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  blend_->use();
  // The mesh vertices a visible triangle uses (the marks of set_marks), where the view marked them:
  // the others keep their last blend, which no visible triangle interpolates.
  const GLuint textures[4] = {target_->colour_texture(), blend_corners_.id(), blend_weights_.id(), marks_[0].id()};
  const char* names[4] = {"u_pass_values", "u_blend_corners", "u_blend_weights", "u_blend_marks"};
  GLint kept[4] = {0, 0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    glActiveTexture(GL_TEXTURE0 + kBlendUnit + i);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &kept[i]);
    glBindTexture(GL_TEXTURE_2D, textures[i]);
    glUniform1i(blend_->uniform(names[i]), kBlendUnit + i);
  }
  glUniform1i(blend_->uniform("u_pass_width"), width_);
  glUniform1i(blend_->uniform("u_pass_rows"), height_);
  glUniform1i(blend_->uniform("u_mesh_width"), mesh_width_);
  glUniform1i(blend_->uniform("u_mesh_rows"), mesh_height_);
  glUniform1i(blend_->uniform("u_mesh_count"), mesh_count_);
  glUniform1i(blend_->uniform("u_blend_cull"), whole ? 0 : 1);
  glUniform1ui(blend_->uniform("u_blend_stamp"), blend_stamp_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  for (int i = 0; i < 4; ++i) {
    glActiveTexture(GL_TEXTURE0 + kBlendUnit + i);
    glBindTexture(GL_TEXTURE_2D, GLuint(kept[i]));
  }
  glActiveTexture(GLenum(active));
  glUseProgram(GLuint(program));
}

void VertexPass::run_blocks(std::span<const GlProgram* const> block_programs, int first_unit, std::span<const int> block_shares) {
  if (block_programs.size() != block_shares.size() || block_programs.empty())
    throw GpuError("per-vertex pass: a program and a share per block");
  const int blocks = int(block_shares.size());
  std::vector<int> shares(static_cast<size_t>(blocks));  // each block's, at most one vertex a share
  for (int b = 0; b < blocks; ++b) shares[size_t(b)] = std::clamp(block_shares[size_t(b)], 1, std::max(count_, 1));
  const bool reuse = std::any_of(shares.begin(), shares.end(), [](int s) { return s > 1; });
  start_run();
  gaps_.assign(size_t(blocks), 0.0f);
  if (!reuse || valid_blocks_ != blocks) {
    draw_blocks(block_programs, first_unit, std::vector<std::pair<int, int>>(size_t(blocks), {0, count_}));
    valid_blocks_ = blocks;
    calls_ = 0;
    // Every value shown is from now on: no chord reaches back past this run (the fabric, the
    // lighting or the view may have jumped).
    floor_ = now_;
    run_times_.assign(1, now_);
    return;
  }
  ++calls_;
  std::vector<std::pair<int, int>> ranges(size_t(blocks), {0, count_});
  for (int b = 0; b < blocks; ++b) {
    const long s = (calls_ - 1) % shares[size_t(b)];
    ranges[size_t(b)] = {int(long(count_) * s / shares[size_t(b)]), int(long(count_) * (s + 1) / shares[size_t(b)])};
  }
  if (history_) copy_to_history(ranges);
  draw_blocks(block_programs, first_unit, ranges);
  if (!history_) return;
  run_times_.push_back(now_);
  constexpr size_t kKeptRuns = 512;
  if (run_times_.size() > kKeptRuns) run_times_.erase(run_times_.begin(), run_times_.end() - kKeptRuns);
  // A texel's two latest computations are a whole round of its block's shares apart (the vertices
  // that come into view between turns: less); half a round more allows for frame times that vary.
  for (int b = 0; b < blocks; ++b) {
    const size_t round = size_t(shares[size_t(b)]);
    if (round > 1 && run_times_.size() > round) gaps_[size_t(b)] = 1.5f * (now_ - run_times_[run_times_.size() - 1 - round]);
  }
}

void VertexPass::set_history(bool on) {
  history_ = on && !subset_;  // a blend has no chord of its own
  if (!on) previous_.reset();
  valid_blocks_ = 0;  // the first run with history is whole: it starts the chords
}

void VertexPass::start_run() {
  if (!history_) return;
  constexpr double kEpochSeconds = 3600.0;  // a float's step at an hour is 0.25 ms: ample for a frame's time
  if (!epoch_set_ || clock_ < epoch_ + double(now_) || clock_ - epoch_ > kEpochSeconds) {
    epoch_ = clock_;
    epoch_set_ = true;
    valid_blocks_ = 0;
    if (previous_) clear_history();  // no chord may join times of two epochs
  }
  now_ = float(clock_ - epoch_);
}

void VertexPass::clear_history() {
  // Not previous_->bind(): that sets the viewport, which the caller keeps; a clear ignores it but
  // not the scissor.
  GLint framebuffer = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer);
  const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, previous_->framebuffer());
  const GLfloat never[4] = {0.0f, 0.0f, 0.0f, -1e30f};  // every texel's time before any floor
  glClearBufferfv(GL_COLOR, 0, never);
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer));
  if (scissor) glEnable(GL_SCISSOR_TEST);
}

void VertexPass::copy_to_history(const std::vector<std::pair<int, int>>& ranges) {
  if (!target_) return;
  // The caller's framebuffers, taken before a new target binds its own.
  GLint read = 0, draw = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
  if (!previous_ || previous_->width() != target_->width() || previous_->height() != target_->height()) {
    previous_ = std::make_unique<OffscreenTarget>(target_->width(), target_->height(), /*full_float=*/true);
    clear_history();
  }
  const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_->framebuffer());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, previous_->framebuffer());
  // Exactly the range's texels: a texel copied out of its turn would lose its chord.
  for (size_t b = 0; b < ranges.size(); ++b) {
    const int base = int(b) * height_;
    range_rectangles(ranges[b].first, ranges[b].second, width_, [&](int x0, int x1, int y0, int y1) {
      glBlitFramebuffer(x0, base + y0, x1, base + y1, x0, base + y0, x1, base + y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    });
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw));
  if (scissor) glEnable(GL_SCISSOR_TEST);
}

void VertexPass::bind_history(const GlProgram& program, int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, previous_ ? previous_->colour_texture() : results()->colour_texture());
  glUniform1i(program.uniform("u_vertex_history"), unit);
  glUniform1f(program.uniform("u_history_now"), now_);
  glUniform1f(program.uniform("u_history_floor"), floor_);
  // The last run's blocks (all 0 without history: no chords).
  std::vector<float> gaps(std::max<size_t>(gaps_.size(), 1), 0.0f);
  if (history_ && previous_) std::copy(gaps_.begin(), gaps_.end(), gaps.begin());
  glUniform1fv(program.uniform("u_history_gap"), GLsizei(gaps.size()), gaps.data());
}

void VertexPass::draw_blocks(std::span<const GlProgram* const> programs, int first_unit,
                             const std::vector<std::pair<int, int>>& ranges) {
  const StageScope stage(Stage::vertex_pass);
  const CallerState caller;  // before a larger target is made: making one binds its framebuffer
  const int blocks = int(ranges.size());
  bool whole = std::all_of(ranges.begin(), ranges.end(), [&](const auto& r) { return r.first == 0 && r.second >= count_; });
  if (blocks > target_blocks_) {  // the target grows to the most blocks asked for
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (long(height_) * blocks > max_size)
      throw GpuError("per-vertex pass: " + std::to_string(blocks) + " values per vertex for " + std::to_string(count_) +
                     " vertices need " + std::to_string(long(height_) * blocks) + " rows, more than the GL's " +
                     std::to_string(max_size));
    target_ = std::make_unique<OffscreenTarget>(width_, height_ * blocks, /*full_float=*/true);
    target_blocks_ = blocks;
    valid_blocks_ = 0;
    whole = true;  // a new target holds nothing to keep
  }
  if (blocks > kMaxBlocks) throw GpuError("per-vertex pass: at most " + std::to_string(kMaxBlocks) + " blocks");
  target_->bind();
  glViewport(0, 0, width_, height_ * blocks);  // the blocks asked for; a larger target's others go unread
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  std::vector<const GlProgram*> done;
  for (const GlProgram* program : programs) {
    if (std::find(done.begin(), done.end(), program) != done.end()) continue;
    done.push_back(program);
    std::vector<bool> mine(ranges.size());
    for (int b = 0; b < blocks; ++b) mine[size_t(b)] = programs[size_t(b)] == program;
    draw_program_blocks(*program, first_unit, ranges, mine, whole);
  }
}

void VertexPass::draw_program_blocks(const GlProgram& program, int first_unit, const std::vector<std::pair<int, int>>& ranges,
                                     const std::vector<bool>& mine, bool whole) {
  const int blocks = int(ranges.size());
  program.use();
  const GlTexture* inputs[3] = {&position_, &normal_, &warp_};
  const char* names[3] = {"u_vertex_position", "u_vertex_normal", "u_vertex_warp"};
  for (int i = 0; i < 3; ++i) {
    glActiveTexture(GL_TEXTURE0 + first_unit + i);
    glBindTexture(GL_TEXTURE_2D, inputs[i]->id());
    glUniform1i(program.uniform(names[i]), first_unit + i);
  }
  glUniform1i(program.uniform("u_vertex_width"), width_);
  glUniform1i(program.uniform("u_vertex_rows"), height_);
  glUniform1i(program.uniform("u_vertex_count"), count_);
  glUniform1i(program.uniform("u_vertex_mesh_width"), mesh_width_);
  glUniform1i(program.uniform("u_vertex_mesh_rows"), mesh_height_);
  glUniform1f(program.uniform("u_pass_time"), now_);
  const GlTexture* marks[2] = {&marks_[current_marks_], &marks_[1 - current_marks_]};
  const char* mark_names[2] = {"u_vertex_mark", "u_vertex_mark_before"};
  for (int i = 0; i < 2; ++i) {  // bound culled or not: each declared sampler needs a texture of its type
    glActiveTexture(GL_TEXTURE0 + kMarkUnit + i);
    glBindTexture(GL_TEXTURE_2D, marks[i]->id());
    glUniform1i(program.uniform(mark_names[i]), kMarkUnit + i);
  }
  glUniform1i(program.uniform("u_vertex_cull"), marked_ ? 1 : 0);
  if (marked_) {
    glUniform1ui(program.uniform("u_vertex_stamp"), stamp_);
    glUniform1ui(program.uniform("u_vertex_stamp_before"), previous_stamp_);
    std::vector<GLint> r;
    for (const auto& [begin, end] : ranges) r.insert(r.end(), {begin, end});
    glUniform2iv(program.uniform("u_vertex_range"), blocks, r.data());
  }
  const bool all_mine = std::all_of(mine.begin(), mine.end(), [](bool m) { return m; });
  if ((whole || marked_) && all_mine) {  // culled: the shader keeps what is outside a block's range (u_vertex_range)
    glDisable(GL_SCISSOR_TEST);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return;
  }
  glEnable(GL_SCISSOR_TEST);
  if (whole || marked_) {  // each run of this program's blocks: its rows
    for (int b = 0; b < blocks;) {
      if (!mine[size_t(b)]) {
        ++b;
        continue;
      }
      int e = b;
      while (e < blocks && mine[size_t(e)]) ++e;
      glScissor(0, b * height_, width_, (e - b) * height_);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      b = e;
    }
    return;
  }
  // Each block's range, by scissor rectangles.
  for (int b = 0; b < blocks; ++b) {
    if (!mine[size_t(b)]) continue;
    range_rectangles(ranges[size_t(b)].first, ranges[size_t(b)].second, width_, [&](int x0, int x1, int y0, int y1) {
      glScissor(x0, b * height_ + y0, x1 - x0, y1 - y0);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    });
  }
}

void VertexPass::bind_result(const GlProgram& program, int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, results()->colour_texture());
  glUniform1i(program.uniform("u_vertex_radiance"), unit);
  glUniform1i(program.uniform("u_vertex_width"), mesh_width_);
  glUniform1i(program.uniform("u_vertex_rows"), mesh_height_);
}

}  // namespace weft::gpu
