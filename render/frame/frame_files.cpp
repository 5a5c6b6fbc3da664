#include "frame/frame_files.h"

#include <iostream>

#include <nlohmann/json.hpp>

#include "image/image.h"

namespace weft {

namespace {

std::filesystem::path png_beside(const std::filesystem::path& exr) {
  auto p = exr;
  p.replace_extension(".png");
  return p;
}

}  // namespace

void write_gpu_frame(const FrameInputs& in, const GpuFrame& f, const FrameFileOptions& a) {
  const std::filesystem::path out(a.out);
  write_exr(f.image, out);
  const double exposure = a.exposure > 0.0 ? a.exposure : auto_exposure(f.image, f.cloth, a.exposure_bias);
  write_png(f.image, png_beside(out), exposure);
  nlohmann::ordered_json j;
  j["scene"] = in.scene.name;
  j["method"] = a.method;
  j["width"] = a.width;
  j["height"] = a.height;
  j["renderer"] = f.renderer;
  j["median_ms"] = f.median_ms;
  j["frames"] = f.frames;
  j["out"] = a.out;
  j["png_exposure"] = exposure;
  std::cout << j.dump() << "\n";
}

void render_reference_frame(const FrameInputs& in, const ReferenceLighting& lighting, const FrameFileOptions& a,
                            const ReferenceFrameOptions& rf, std::function<void(double)> progress) {
  const std::filesystem::path out(a.out);
  ReferenceRenderOptions opt;
  opt.width = a.width;
  opt.height = a.height;
  opt.sg_grid = rf.sg_grid;
  opt.tangent_samples = rf.tangent_samples;
  opt.check_stride = rf.check_stride;
  opt.check_convergence = rf.check_convergence;
  opt.resolved_weave = rf.resolved_weave;
  opt.supersample = rf.supersample;
  opt.progress = std::move(progress);

  std::cerr << "weft render: scene " << in.scene.name << ", " << a.width << "x" << a.height << ", lighting "
            << lighting.description
            << (rf.lighting == "sg" ? ", SG grid " + std::to_string(rf.sg_grid) + "x" + std::to_string(2 * rf.sg_grid) + " per SG, "
                                    : std::string(", "))
            << rf.tangent_samples << " tangent samples per thread"
            << (rf.resolved_weave ? ", resolved weave" : "")
            << (rf.supersample > 1 ? ", " + std::to_string(rf.supersample * rf.supersample) + " rays per pixel" : std::string())
            << "\n";
  const ReferenceRenderer renderer(in.scene, in.fabrics, lighting, opt);
  const ReferenceRenderResult r = renderer.render(0);
  write_exr(r.image, out);
  std::vector<bool> cloth(r.kinds.size());
  for (size_t i = 0; i < r.kinds.size(); ++i) cloth[i] = r.kinds[i] == PixelKind::cloth;
  const double exposure = a.exposure > 0.0 ? a.exposure : auto_exposure(r.image, cloth, a.exposure_bias);
  write_png(r.image, png_beside(out), exposure);

  nlohmann::ordered_json j;
  j["scene"] = in.scene.name;
  j["method"] = a.method;
  j["lighting"] = rf.lighting;
  j["environment"] = in.env;
  j["width"] = a.width;
  j["height"] = a.height;
  j["lighting_description"] = lighting.description;
  if (rf.lighting == "sg") j["sg_grid"] = rf.sg_grid;
  else j["map_width"] = rf.map_width;
  j["tangent_samples"] = rf.tangent_samples;
  j["seconds"] = r.seconds;
  j["exr"] = out.string();
  j["png"] = png_beside(out).string();
  j["png_exposure"] = exposure;
  if (opt.check_convergence) {
    const auto& c = r.convergence;
    j["convergence"] = {{"compared_with", "2x lighting resolution and 2x tangent samples"},
                        {"check_stride", rf.check_stride},
                        {"pixels_checked", c.pixels_checked},
                        {"relative_rmse", c.relative_rmse},
                        {"cloth_relative_rmse", c.cloth_relative_rmse},
                        {"max_pixel_change", c.max_pixel_change},
                        {"seconds", c.seconds}};
    std::cerr << "weft render: done in " << r.seconds << " s; convergence (1 in " << rf.check_stride * rf.check_stride
              << " pixels at twice the lighting resolution and tangent samples): relative RMSE " << 100 * c.relative_rmse << " % (cloth "
              << 100 * c.cloth_relative_rmse << " %), max pixel change " << 100 * c.max_pixel_change << " %\n";
  } else {
    std::cerr << "weft render: done in " << r.seconds << " s (convergence not checked)\n";
  }
  std::cout << j.dump() << "\n";
}

}  // namespace weft
