#pragma once
// A rendered frame's files and summary, as `weft render` writes them: the EXR (linear
// radiance), a tone-mapped PNG beside it, and one JSON line on stdout.
#include <filesystem>
#include <functional>
#include <string>

#include "frame/frame_inputs.h"
#include "frame/frame_render.h"

namespace weft {

struct FrameFileOptions {
  std::string method;
  std::string out;        // the .exr; the .png goes beside it
  int width = 320, height = 240;
  double exposure = 0.0;  // PNG exposure; 0: metered on the cloth (image/tone_map.h)
  double exposure_bias = 0.0;  // EV added to the metered exposure
};

// A GPU method's frame (render_gpu_frame).
void write_gpu_frame(const FrameInputs& in, const GpuFrame& f, const FrameFileOptions& o);

struct ReferenceFrameOptions {
  std::string lighting = "sg";  // as FrameLightingOptions::mode, for the summary
  int sg_grid = 8, map_width = 128, tangent_samples = 32, check_stride = 6;
  bool check_convergence = true;
  bool resolved_weave = false;  // ReferenceRenderOptions::resolved_weave
  int supersample = 1;
};

// Renders `reference` (logging the setup and the convergence check on stderr, progress through
// `progress`), then writes it.
void render_reference_frame(const FrameInputs& in, const ReferenceLighting& lighting, const FrameFileOptions& o,
                            const ReferenceFrameOptions& r, std::function<void(double)> progress);

}  // namespace weft
