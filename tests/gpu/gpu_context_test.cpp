// The headless GLES path on whatever EGL offers (llvmpipe here): a context, a float target, a
// program, and exact read-back of what a shader wrote.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/egl_context.h"
#include "gl/gl_program.h"
#include "gl/offscreen_target.h"

using namespace weft::gpu;

static const char* kFullscreenVs = R"(#version 300 es
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  gl_Position = vec4(p, 0.0, 1.0);
})";

TEST(GpuContext, HeadlessGles3RendersFloatsExactly) {
  EglContext ctx = EglContext::headless();
  EXPECT_NE(ctx.version().find("OpenGL ES 3"), std::string::npos) << ctx.version();
  OffscreenTarget target(37, 23);
  GlProgram prog(kFullscreenVs, R"(#version 300 es
precision highp float;
out vec4 colour;
void main() {
  // Values a half-float target could not hold: pins the 32-bit path.
  colour = vec4(gl_FragCoord.x * 1e-3 + 1e4, gl_FragCoord.y, 1.0 / 3.0, -2.5e-6);
})");
  target.bind();
  prog.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  const auto px = target.read_rgba();
  ASSERT_EQ(px.size(), 37u * 23u * 4u);
  for (int y = 0; y < 23; y += 5)
    for (int x = 0; x < 37; x += 6) {
      const float* p = &px[(size_t(y) * 37 + x) * 4];
      EXPECT_FLOAT_EQ(p[0], (x + 0.5f) * 1e-3f + 1e4f);
      EXPECT_FLOAT_EQ(p[1], y + 0.5f);
      EXPECT_FLOAT_EQ(p[2], 1.0f / 3.0f);
      EXPECT_FLOAT_EQ(p[3], -2.5e-6f);
    }
}

TEST(GpuContext, ShaderErrorsNameTheLine) {
  EglContext ctx = EglContext::headless();
  try {
    GlProgram bad(kFullscreenVs, "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(undefined_thing); }\n");
    FAIL() << "a broken shader linked";
  } catch (const GpuError& e) {
    EXPECT_NE(std::string(e.what()).find("undefined_thing"), std::string::npos) << e.what();
  }
}

TEST(GpuContext, AbsurdTargetSizeIsAnError) {
  EglContext ctx = EglContext::headless();
  EXPECT_THROW(OffscreenTarget(0, 10), GpuError);
  EXPECT_THROW(OffscreenTarget(100000, 10), GpuError);
}
