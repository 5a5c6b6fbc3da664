#pragma once
// One headless GLES frame of a scene with a runtime method, read back as linear radiance, and
// the median frame time (`weft render` and `weft bench` draw their GPU frames with this).
#include <map>
#include <memory>
#include <string>

#include "runtime/iwasaki_bundle.h"
#include "core/fabric.h"
#include "core/spherical_gaussian.h"
#include "image/image.h"
#include "scene/scene.h"

namespace weft {

struct GpuFrame {
  Image image;
  std::string renderer;     // GL_RENDERER
  double median_ms = 0.0;   // median frame time over `frames` frames after a warm-up, glFinish included
  int frames = 0;
};

GpuFrame render_gpu_frame(const Scene& scene, const std::map<std::string, Fabric>& fabrics, const SgLighting& sgs,
                          const std::string& method, int width, int height, int timed_frames,
                          std::shared_ptr<const IwasakiBundleData> iwasaki = nullptr);

}  // namespace weft
