// The per-vertex pass's temporal reuse (methods/iwasaki/vertex_pass.h): with a program that writes
// the call number into every texel it computes, each vertex of each block must hold the call at
// which its block's share last covered it — every vertex once per `shares` calls, no vertex twice,
// none skipped — with a rate per block, and a whole pass after invalidate(); with a program per
// block, each block drawn by its own.
#include <GLES3/gl31.h>
#include <gtest/gtest.h>

#include <vector>

#include "gl/gl_program.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "methods/iwasaki/vertex_pass.h"
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
