// The per-vertex pass's temporal reuse (methods/vertex_pass/vertex_pass.h): with a program that writes
// the call number into every texel it computes, each vertex of each block must hold the call at
// which its block's share last covered it — every vertex once per `shares` calls, no vertex twice,
// none skipped — with a rate per block, and a whole pass after invalidate(); with a program per
// block, each block drawn by its own. With history, kept values carried along their chords to the
// frame's time reproduce a value linear in time exactly. Over a subset of a dense mesh's vertices,
// every mesh vertex's value is its three pass vertices' blend, and with marks only the marked ones
// are blended anew.
#include <GLES3/gl31.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl_program.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "methods/vertex_pass/vertex_pass.h"
#include "scene/procedural_meshes.h"
#include "scene/vertex_pass_mesh.h"
#include "shaders/embedded_shaders.h"

using namespace weft;

namespace {
// Writes (call, vertex, block, 1) at every texel of a vertex.
const std::string kPassFs = std::string("#version 300 es\nprecision highp float;\nprecision highp int;\n") +
                            std::string(shaders::source("vertex_pass.glsl")) + R"(
uniform float u_call;
uniform float u_tag;  // which program drew the texel
out vec4 o_value;
void main() {
  PassTexel t = pass_texel();
  if (pass_keeps(t)) discard;
  o_value = vec4(u_call, float(t.i), float(t.k), u_tag);
}
)";

TriangleMesh line_of_vertices(int n) {
  TriangleMesh m;
  for (int i = 0; i < n; ++i) {
    m.positions.push_back({double(i), 0.0, 0.0});
    m.normals.push_back({0.0, 0.0, 1.0});
    m.warps.push_back({1.0, 0.0, 0.0});
  }
  return m;
}
}  // namespace

TEST(VertexPass, EachBlockRecomputesItsShareInTurn) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  const int n = 700;  // three texel rows of 256: shares start and end inside rows
  gpu::VertexPass pass(line_of_vertices(n));
  gpu::GlProgram program(gpu::fullscreen_triangle_vs(), kPassFs);
  program.use();
  glUniform1f(program.uniform("u_tag"), 1.0f);
  const std::vector<int> shares = {1, 3, 7};
  // last[b][i]: the call that last computed vertex i of block b, as the pass must have it.
  std::vector<std::vector<int>> last(shares.size(), std::vector<int>(n, 0));
  for (int call = 0; call < 9; ++call) {
    glUniform1f(program.uniform("u_call"), float(call));
    pass.run_shares(program, 0, shares);
    for (size_t b = 0; b < shares.size(); ++b) {
      if (call == 0) {  // nothing kept yet: the whole pass
        std::fill(last[b].begin(), last[b].end(), 0);
        continue;
      }
      const int s = (call - 1) % shares[b];
      for (int i = n * s / shares[b]; i < n * (s + 1) / shares[b]; ++i) last[b][size_t(i)] = call;
    }
    const std::vector<float> texels = pass.read_values();
    const int width = 256, rows = (n + width - 1) / width;
    for (size_t b = 0; b < shares.size(); ++b)
      for (int i = 0; i < n; ++i) {
        const size_t t = (size_t(b) * rows * width + size_t(i)) * 4;
        ASSERT_EQ(texels[t + 1], float(i)) << "vertex " << i << " block " << b;
        ASSERT_EQ(texels[t + 2], float(b));
        ASSERT_EQ(texels[t], float(last[b][size_t(i)])) << "call " << call << " block " << b << " (shares " << shares[b]
                                                          << ") vertex " << i;
      }
  }
  // Every vertex of a block refreshed within its last `shares` calls.
  for (size_t b = 0; b < shares.size(); ++b)
    for (int i = 0; i < n; ++i) EXPECT_GT(last[b][size_t(i)], 8 - shares[b]);
  // invalidate(): the next call is a whole pass again.
  pass.invalidate();
  glUniform1f(program.uniform("u_call"), 42.0f);
  pass.run_shares(program, 0, shares);
  const std::vector<float> texels = pass.read_values();
  for (size_t b = 0; b < shares.size(); ++b)
    for (int i = 0; i < n; ++i) EXPECT_EQ(texels[(size_t(b) * 3 * 256 + size_t(i)) * 4], 42.0f);
}

// A program per block (the quadrature rung's narrow SGs in iwasaki's own program): each block is
// drawn by its own program alone, with the same shares in turn, with and without visible-vertex
// marks (every vertex marked: the marks keep nothing the shares recompute).
TEST(VertexPass, EachBlockIsDrawnByItsOwnProgram) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  const int n = 700, width = 256, rows = 3;
  for (const bool marked : {false, true}) {
    gpu::VertexPass pass(line_of_vertices(n));
    gpu::GlProgram a(gpu::fullscreen_triangle_vs(), kPassFs), b(gpu::fullscreen_triangle_vs(), kPassFs);
    a.use();
    glUniform1f(a.uniform("u_tag"), 1.0f);
    b.use();
    glUniform1f(b.uniform("u_tag"), 2.0f);
    GLuint marks = 0;
    if (marked) {  // one uint per vertex texel, all this view's stamp
      const std::vector<GLuint> stamps(size_t(pass.texels()), 1u);
      glGenBuffers(1, &marks);
      glBindBuffer(GL_PIXEL_UNPACK_BUFFER, marks);
      glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(stamps.size() * sizeof(GLuint)), stamps.data(), GL_STATIC_DRAW);
      glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    }
    const std::vector<const gpu::GlProgram*> programs = {&a, &b, &a, &b};
    const std::vector<int> shares = {1, 3, 1, 7};
    std::vector<std::vector<int>> last(shares.size(), std::vector<int>(n, 0));
    for (int call = 0; call < 8; ++call) {
      for (const gpu::GlProgram* p : {&a, &b}) {
        p->use();
        glUniform1f(p->uniform("u_call"), float(call));
      }
      if (marked) pass.set_marks(marks, 1u);
      pass.run_shares(programs, 0, shares);
      for (size_t k = 0; k < shares.size() && call > 0; ++k) {
        const int s = (call - 1) % shares[k];
        for (int i = n * s / shares[k]; i < n * (s + 1) / shares[k]; ++i) last[k][size_t(i)] = call;
      }
      const std::vector<float> texels = pass.read_values();
      for (size_t k = 0; k < shares.size(); ++k)
        for (int i = 0; i < n; ++i) {
          const size_t t = (k * rows * width + size_t(i)) * 4;
          ASSERT_EQ(texels[t + 3], k % 2 == 0 ? 1.0f : 2.0f) << "block " << k << " vertex " << i << (marked ? " (marked)" : "");
          ASSERT_EQ(texels[t + 2], float(k));
          ASSERT_EQ(texels[t], float(last[k][size_t(i)])) << "call " << call << " block " << k << " vertex " << i
                                                          << (marked ? " (marked)" : "");
        }
    }
    if (marks) glDeleteBuffers(1, &marks);
  }
}

namespace {
// Writes a value linear in the run's time, different per vertex and block, with the time in w.
const std::string kLinearFs = std::string("#version 300 es\nprecision highp float;\nprecision highp int;\n") +
                              std::string(shaders::source("vertex_pass.glsl")) + R"(
out vec4 o_value;
vec3 linear_value(int i, int k, float t) { return vec3(1.0 + 0.01 * float(i), 2.0, 3.0 + float(k)) + t * vec3(0.5, -0.25 * float(k + 1), 0.001 * float(i)); }
void main() {
  PassTexel t = pass_texel();
  if (pass_keeps(t)) discard;
  o_value = vec4(linear_value(t.i, t.k, u_pass_time), u_pass_time);
}
)";
// Reads every texel back through vertex_history.glsl's extrapolated_value, as a draw would.
const std::string kReadFs = std::string("#version 300 es\nprecision highp float;\nprecision highp int;\n#define MAX_PASS_VALUES 8\n") +
                            std::string(shaders::source("vertex_history.glsl")) + R"(
uniform highp sampler2D u_vertex_radiance;
uniform int u_vertex_rows;
out vec4 o_value;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  o_value = vec4(extrapolated_value(texelFetch(u_vertex_radiance, p, 0), p, p.y / u_vertex_rows), 0.0);
}
)";
}  // namespace

TEST(VertexPass, HistoryCarriesKeptValuesAlongTheirChords) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  const int n = 700, width = 256, rows = 3;
  const std::vector<int> shares = {3, 5};
  gpu::VertexPass pass(line_of_vertices(n));
  pass.set_history(true);
  gpu::GlProgram program(gpu::fullscreen_triangle_vs(), kLinearFs), read(gpu::fullscreen_triangle_vs(), kReadFs);
  gpu::OffscreenTarget out(width, rows * int(shares.size()));
  auto linear = [](int i, int k, double t) {
    return glm::dvec3(1.0 + 0.01 * i, 2.0, 3.0 + k) + t * glm::dvec3(0.5, -0.25 * (k + 1), 0.001 * i);
  };
  // What a draw shows: every texel read through extrapolated_value into `out`.
  auto shown_now = [&] {
    out.bind();
    glViewport(0, 0, width, rows * int(shares.size()));
    read.use();
    pass.bind_result(read, 0);
    pass.bind_history(read, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return out.read_rgba();
  };
  const double start = 1000.0, frame = 0.07;
  size_t carried = 0;
  for (int call = 0; call < 16; ++call) {
    const double now = start + frame * call;
    pass.set_clock(now);
    program.use();
    pass.run_shares(program, 0, shares);
    const std::vector<float> shown = shown_now(), kept = pass.read_values();
    for (size_t k = 0; k < shares.size(); ++k)
      for (int i = 0; i < n; ++i) {
        const size_t t = (k * rows * width + size_t(i)) * 4;
        // The pass's time runs from its first run.
        const glm::dvec3 exact = linear(i, int(k), now - start);
        const double computed_at = kept[t + 3];
        // A whole round of shares after the first share run, every vertex has two computations in
        // its chord: the value shown is the linear value now; before, some are kept as they are.
        const bool chord = call > 2 * shares[k];
        for (int c = 0; c < 3; ++c) {
          const double expected = chord ? exact[c] : linear(i, int(k), computed_at)[c];
          if (!chord && std::abs(shown[t + size_t(c)] - expected) > 1e-4) {  // carried early: still exact
            ASSERT_NEAR(shown[t + size_t(c)], exact[c], 1e-4) << "call " << call << " block " << k << " vertex " << i;
            continue;
          }
          ASSERT_NEAR(shown[t + size_t(c)], expected, 1e-4) << "call " << call << " block " << k << " vertex " << i;
        }
        if (computed_at < (now - start) - 1e-6) ++carried;
      }
  }
  EXPECT_GT(carried, size_t(n));  // kept values were shown, carried on
  // After invalidate() (a knob, a light): a whole pass, and no chord reaches back past it.
  pass.invalidate();
  const double now = start + frame * 16 + 5.0;  // and the values jump: another fabric
  pass.set_clock(now);
  program.use();
  pass.run_shares(program, 0, shares);
  pass.set_clock(now + frame);
  pass.run_shares(program, 0, shares);
  const std::vector<float> shown = shown_now(), kept = pass.read_values();
  for (size_t k = 0; k < shares.size(); ++k)
    for (int i = 0; i < n; ++i) {
      const size_t t = (k * rows * width + size_t(i)) * 4;
      for (int c = 0; c < 3; ++c) ASSERT_EQ(shown[t + size_t(c)], kept[t + size_t(c)]) << "block " << k << " vertex " << i;
    }
  // A clock that steps back starts a new epoch (the history cleared, a whole pass): the caller's
  // framebuffer and viewport stay as they were, as after any run.
  out.bind();
  glViewport(3, 2, 17, 9);
  pass.set_clock(start);
  pass.run_shares(program, 0, shares);
  GLint viewport[4] = {0, 0, 0, 0}, framebuffer = 0;
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer);
  EXPECT_EQ(GLuint(framebuffer), out.framebuffer());
  EXPECT_EQ(std::vector<GLint>(viewport, viewport + 4), (std::vector<GLint>{3, 2, 17, 9}));
}

// With marks, a visible vertex seen within ~3° of edge-on (|n·ω_o| < 0.05) is recomputed at every
// run, its share's turn or not: the line's normals are +z, and from an eye 10 above the first
// vertex, those from x ≈ 200 on are edge-on.
TEST(VertexPass, EdgeOnVerticesAreRecomputedEveryRun) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  const int n = 700;
  const std::string fs = std::string("#version 300 es\nprecision highp float;\nprecision highp int;\n") +
                         std::string(shaders::source("vertex_pass.glsl")) + R"(
uniform float u_call;
out vec4 o_value;
void main() {
  PassTexel t = pass_texel();
  if (pass_keeps_turn(t, vec3(0.0, 0.0, 10.0))) discard;
  o_value = vec4(u_call, 0.0, 0.0, 1.0);
}
)";
  gpu::VertexPass pass(line_of_vertices(n));
  gpu::GlProgram program(gpu::fullscreen_triangle_vs(), fs);
  const std::vector<GLuint> stamps(size_t(pass.texels()), 1u);  // every vertex visible
  GLuint marks = 0;
  glGenBuffers(1, &marks);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, marks);
  glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(stamps.size() * sizeof(GLuint)), stamps.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  const std::vector<int> shares = {7};
  std::vector<int> last(n, 0);
  for (int call = 0; call < 9; ++call) {
    program.use();
    glUniform1f(program.uniform("u_call"), float(call));
    pass.set_marks(marks, 1u);
    pass.run_shares(program, 0, shares);
    const int s = (call - 1) % shares[0];
    for (int i = 0; i < n; ++i) {
      const bool edge_on = 10.0 / std::sqrt(100.0 + double(i) * i) < 0.05;
      if (call == 0 || edge_on || (i >= n * s / shares[0] && i < n * (s + 1) / shares[0])) last[size_t(i)] = call;
    }
    const std::vector<float> texels = pass.read_values();
    for (int i = 0; i < n; ++i)
      ASSERT_EQ(texels[size_t(i) * 4], float(last[size_t(i)])) << "call " << call << " vertex " << i;
  }
  EXPECT_EQ(last[size_t(n - 1)], 8);  // an edge-on vertex: the last run's
  EXPECT_LT(last[150], 8);            // one seen from above, out of the last run's share: its share's
  glDeleteBuffers(1, &marks);
}

// Over a subset of a dense sheet's vertices (scene/vertex_pass_mesh.h), a program writing each
// pass vertex's own position plus its block lands, blended, on every mesh vertex's own position
// plus the block (the sheet is flat: its blend of a linear function is exact), in the layout the
// draws read (mesh vertex i at (i mod 256, i div 256) of each block); the kept pass vertices
// carry their own mesh index.
TEST(VertexPass, SubsetPassBlendsEveryMeshVertexFromItsCorners) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  const std::string fs = std::string("#version 300 es\nprecision highp float;\nprecision highp int;\n") +
                         std::string(shaders::source("vertex_pass.glsl")) + R"(
out vec4 o_value;
void main() {
  PassTexel t = pass_texel();
  if (t.past) {
    o_value = vec4(0.0);
    return;
  }
  o_value = vec4(texelFetch(u_vertex_position, t.p, 0).xyz + vec3(float(t.k)), float(t.i));
}
)";
  TriangleMesh sheet = parametric_grid(90, 90, [](double s, double t) { return glm::dvec3(0.5 * s, 0.3 * t, 0.0); });
  finish_mesh(sheet, true, "sheet");
  const VertexPassMesh subset = vertex_pass_mesh(sheet);
  ASSERT_FALSE(subset.whole());
  gpu::VertexPass pass(sheet, subset);
  EXPECT_EQ(pass.pass_vertices(), int(subset.vertices.size()));
  const int n = int(sheet.positions.size()), width = 256, rows = (n + width - 1) / width;
  EXPECT_EQ(pass.texels(), width * rows);
  gpu::GlProgram program(gpu::fullscreen_triangle_vs(), fs);
  const int blocks = 3;
  pass.run(program, 0, blocks);
  const std::vector<float> texels = pass.read_values();
  ASSERT_GE(texels.size(), size_t(width) * rows * blocks * 4);
  std::vector<bool> kept(size_t(n), false);
  for (uint32_t v : subset.vertices) kept[v] = true;
  for (int b = 0; b < blocks; ++b)
    for (int i = 0; i < n; ++i) {
      const size_t t = (size_t(b) * rows * width + size_t(i)) * 4;
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(texels[t + c], float(sheet.positions[size_t(i)][c] + b), 1e-4) << "vertex " << i << " block " << b;
      if (kept[size_t(i)]) {
        ASSERT_EQ(texels[t + 3], float(i)) << "pass vertex " << i;
      }
    }
  // With the view's marks, only the marked mesh vertices are blended anew (here: the first third,
  // after the pass writes its positions shifted by 10); the others keep their last blend.
  const GLuint stamp = 7;
  std::vector<GLuint> stamps(size_t(pass.texels()), 0u);
  for (int i = 0; i < n / 3; ++i) stamps[size_t(i)] = stamp;
  GLuint marks = 0;
  glGenBuffers(1, &marks);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, marks);
  glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(stamps.size() * sizeof(GLuint)), stamps.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  const std::string shifted = std::string("#version 300 es\nprecision highp float;\nprecision highp int;\n") +
                              std::string(shaders::source("vertex_pass.glsl")) + R"(
out vec4 o_value;
void main() {
  PassTexel t = pass_texel();
  o_value = t.past ? vec4(0.0) : vec4(texelFetch(u_vertex_position, t.p, 0).xyz + vec3(10.0 + float(t.k)), float(t.i));
}
)";
  gpu::GlProgram again(gpu::fullscreen_triangle_vs(), shifted);
  pass.set_marks(marks, stamp);
  pass.run(again, 0, blocks);
  const std::vector<float> after = pass.read_values();
  for (int b = 0; b < blocks; ++b)
    for (int i = 0; i < n; ++i) {
      const size_t t = (size_t(b) * rows * width + size_t(i)) * 4;
      const double shift = i < n / 3 ? 10.0 : 0.0;
      ASSERT_NEAR(after[t], float(sheet.positions[size_t(i)].x + b + shift), 1e-4) << "vertex " << i << " block " << b;
    }
  glDeleteBuffers(1, &marks);
}
