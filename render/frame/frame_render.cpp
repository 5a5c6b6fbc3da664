#include "frame/frame_render.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "bake/tables/table_baker.h"
#include "gpu/egl_context.h"
#include "gl/offscreen_target.h"
#include "gpu/scene_renderer.h"
#include "methods/registry.h"

namespace weft {

GpuFrame render_gpu_frame(const Scene& scene, const std::map<std::string, Fabric>& fabrics, const SgLighting& sgs,
                          const std::string& method, int width, int height, int timed_frames,
                          std::shared_ptr<const ShadingData> shading, gpu::Backdrop backdrop, bool weave,
                          bool weave_pixel_terms) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  std::vector<Fabric> cloth;
  for (const auto& o : scene.cloth_objects()) cloth.push_back(object_base_fabric(o, fabrics));
  gpu::SceneRenderer renderer(scene, cloth, methods::method(method), 16, std::move(shading), table_baker());
  for (const std::string& w : renderer.warnings()) std::fprintf(stderr, "weft render: %s\n", w.c_str());
  renderer.set_lighting(sgs);
  renderer.set_backdrop(backdrop);
  renderer.set_weave(weave);
  renderer.set_weave_pixel_terms(weave_pixel_terms);
  gpu::OffscreenTarget target(width, height);
  target.bind();
  renderer.draw(scene.camera, width, height);  // warm-up: shader compilation, first upload
  glFinish();
  std::vector<double> ms;
  for (int i = 0; i < timed_frames; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    renderer.draw(scene.camera, width, height);
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  GpuFrame f;
  const std::vector<float> rgba = target.read_rgba();  // row 0 at the bottom
  f.image = Image(width, height);
  f.cloth.resize(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* p = &rgba[(size_t(height - 1 - y) * width + x) * 4];
      f.image.at(x, y) = glm::dvec3(p[0], p[1], p[2]);
      f.cloth[size_t(y) * width + x] = gpu::is_cloth_alpha(p[3]);
    }
  f.renderer = ctx.renderer();
  f.frames = timed_frames;
  if (!ms.empty()) {
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    f.median_ms = ms[ms.size() / 2];
  }
  return f;
}

}  // namespace weft
