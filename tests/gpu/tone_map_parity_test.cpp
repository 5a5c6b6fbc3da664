// The kiosk's GLSL tone mapper (gpu::ToneMapper, render/shaders/tonemap.frag) against the C++
// operator write_png uses (image/tone_map.h): one radiance ramp from black past the white
// point, several exposures, compared before 8-bit quantisation.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "gpu/scene_renderer.h"
#include "image/tone_map.h"

using namespace weft;

TEST(ToneMapParity, GlslOperatorMatchesTheCppOne) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  const int n = 256;
  std::vector<float> radiance(size_t(n) * 4, 1.0f);
  std::vector<double> values(n);
  for (int i = 0; i < n; ++i) {
    // 0, then log-spaced 1e-4 … 40: the toe, the linear part, the shoulder and past white.
    values[i] = i == 0 ? 0.0 : 1e-4 * std::pow(4e5, double(i - 1) / (n - 2));
    for (int c = 0; c < 3; ++c) radiance[size_t(i) * 4 + c] = float(values[i] * (1.0 + 0.25 * c));
  }
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, n, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n, 1, GL_RGBA, GL_FLOAT, radiance.data());
  const gpu::ToneMapper tonemap;
  gpu::OffscreenTarget out(n, 1);
  double worst = 0.0;
  for (double exposure : {0.05, 1.0, 3.7}) {
    out.bind();
    glViewport(0, 0, n, 1);
    tonemap.draw(tex, float(exposure));
    const std::vector<float> px = out.read_rgba();
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        const double expect = display_value(double(radiance[size_t(i) * 4 + c]), double(float(exposure)));
        const double got = px[size_t(i) * 4 + c];
        worst = std::max(worst, std::abs(got - expect));
        ASSERT_NEAR(got, expect, 2e-4) << "radiance " << radiance[size_t(i) * 4 + c] << " exposure " << exposure;
      }
  }
  glDeleteTextures(1, &tex);
  std::printf("worst |GLSL - C++| %.2e (of 1; an 8-bit step is 3.9e-3)\n", worst);
}
