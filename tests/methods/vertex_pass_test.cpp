// The per-vertex pass's temporal reuse (methods/iwasaki/vertex_pass.h): with a program that writes
// the call number into every texel it computes, each vertex of each block must hold the call at
// which its block's share last covered it — every vertex once per `shares` calls, no vertex twice,
// none skipped — with a rate per block, and a whole pass after invalidate().
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
out vec4 o_value;
void main() {
  PassTexel t = pass_texel();
  o_value = vec4(u_call, float(t.i), float(t.k), 1.0);
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
