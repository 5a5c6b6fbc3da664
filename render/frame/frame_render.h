#pragma once
// One headless GLES frame of a scene with a runtime method, read back as linear radiance, and
// the median frame time (`weft render` and `weft bench` draw their GPU frames with this; the
// bench with Backdrop::measure, `weft render` with the showroom's backdrop).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "runtime/shading_data.h"
#include "core/fabric.h"
#include "core/spherical_gaussian.h"
#include "gpu/scene_renderer.h"
#include "image/image.h"
#include "scene/scene.h"

namespace weft {

struct GpuFrame {
  Image image;
  std::vector<bool> cloth;  // per pixel (as image.pixels): cloth drawn there (gpu::is_cloth_alpha), never the backdrop
  std::string renderer;     // GL_RENDERER
  double median_ms = 0.0;   // median frame time over `frames` frames after a warm-up, glFinish included
  int frames = 0;
};

GpuFrame render_gpu_frame(const Scene& scene, const std::map<std::string, Fabric>& fabrics, const SgLighting& sgs,
                          const std::string& method, int width, int height, int timed_frames,
                          std::shared_ptr<const ShadingData> shading = nullptr,
                          gpu::Backdrop backdrop = gpu::Backdrop::measure, bool weave = false,
                          bool weave_pixel_terms = true);  // gpu::SceneRenderer::set_weave_pixel_terms

}  // namespace weft
