#include "frame/frame_render.h"

#include <algorithm>
#include <chrono>

#include "bake/table_baker.h"
#include "gpu/egl_context.h"
#include "gl/offscreen_target.h"
#include "gpu/scene_renderer.h"

namespace weft {

GpuFrame render_gpu_frame(const Scene& scene, const std::map<std::string, Fabric>& fabrics, const SgLighting& sgs,
                          const std::string& method, int width, int height, int timed_frames,
                          std::shared_ptr<const IwasakiBundleData> iwasaki) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  std::vector<Fabric> cloth;
  for (const auto& o : scene.objects)
    if (o.material == Material::cloth) cloth.push_back(fabrics.at(o.fabric));
  gpu::SceneRenderer renderer(scene, cloth, gpu::parse_method(method), 16, std::move(iwasaki), table_baker());
  renderer.set_lighting(sgs);
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
  f.image = gpu::read_linear_image(width, height);
  f.renderer = ctx.renderer();
  f.frames = timed_frames;
  if (!ms.empty()) {
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    f.median_ms = ms[ms.size() / 2];
  }
  return f;
}

}  // namespace weft
