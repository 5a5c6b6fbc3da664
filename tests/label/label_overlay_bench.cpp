// What the label costs a frame on this machine's GLES (llvmpipe here): the tone-mapped frame
// presented with and without the label over it, as KMS presents it, at 640×480 and 1920×1080;
// and the CPU time to shape and rasterise the text (once per text change). Prints the medians.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <vector>

#include "gl/display_target.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "gpu/scene_renderer.h"
#include "label/label_overlay.h"
#include "label/label_text.h"

namespace weft::label {
namespace {

using Clock = std::chrono::steady_clock;

template <class F>
double median_ms(int n, F f) {
  std::vector<double> ms;
  for (int i = 0; i < n; ++i) {
    const auto t0 = Clock::now();
    f();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

TEST(LabelOverlayBench, PresentWithAndWithoutTheLabel) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  const gpu::ToneMapper tonemap;
  for (const auto [w, h, size] : {std::array{640, 480, 24}, std::array{1920, 1080, 32}}) {
    const LabelFont title(kDefaultFontFile, size), detail(kDefaultFontFile, int(0.7 * size + 0.5));
    const std::vector<LabelLine> lines{{"Linen, plain weave", &title}, {"100 % linen", &detail}};
    CoverageImage img;
    const double raster = median_ms(21, [&] { img = rasterise_lines(lines, std::max(4, size / 3)); });
    LabelOverlay overlay;
    overlay.set_image(img);
    const Box box = place_box(Corner::bottom_left, size, w, h, img.width, img.height);
    const gpu::OffscreenTarget frame(w, h);
    frame.bind();
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const gpu::DisplayTarget screen(w, h);
    const auto present = [&](bool label) {
      screen.bind();
      tonemap.draw(frame.colour_texture(), 1.0f);
      if (label) overlay.draw(box, 1.0f);
      glFinish();
    };
    present(true);  // shaders compiled, textures resident
    double plain = 0, labelled = 0;
    for (int round = 0; round < 3; ++round) {  // interleaved: drift on a shared machine hits both
      plain += median_ms(15, [&] { present(false); }) / 3;
      labelled += median_ms(15, [&] { present(true); }) / 3;
    }
    std::printf("%dx%d, label %dx%d px (size %d): present %.3f ms, with the label %.3f ms (+%.3f ms); text shaped and rasterised in %.3f ms\n",
                w, h, img.width, img.height, size, plain, labelled, labelled - plain, raster);
    const double label_only = median_ms(31, [&] {
      screen.bind();
      overlay.draw(box, 1.0f);
      glFinish();
    });
    std::printf("%dx%d: the label's draw alone %.3f ms\n", w, h, label_only);
  }
}

}  // namespace
}  // namespace weft::label
