// frame_compare: one frame against another of the same view, as the content bench rows need
// them. The frame error is docs/design.md §6's relative RMSE taken over the pixels where the
// measured frame shows a surface (it is drawn over a black backdrop, `weft render --backdrop
// measure`; the reference shows the environment behind: the same triangles, so the same pixels), and the
// artefact measure is measure/detail_energy.h's worst block of fine detail against the other
// frame's. Prints one JSON line; exit 2 on unreadable or mismatched files.
#include <cmath>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "image/image.h"
#include "measure/detail_energy.h"
#include "measure/image_metrics.h"

int main(int argc, char** argv) {
  CLI::App app{"frame_compare: a frame's error against a reference frame over the frame's surface pixels (drawn over black), and "
               "its worst 32×32 block of fine detail against the reference's (or a peer's) frame"};
  std::string method, reference, detail_reference;
  double limit = 2.0;
  app.add_option("method", method, "The frame measured (.exr)")->required();
  app.add_option("reference", reference, "The reference frame (.exr), same size")->required();
  app.add_option("--detail-reference", detail_reference,
                 "Measure fine detail against this frame instead (.exr, same size: e.g. Filament's frame)");
  app.add_option("--limit", limit, "A block is an artefact past this ratio of fine detail")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const weft::Image m = weft::read_exr(method), r = weft::read_exr(reference);
    if (m.width != r.width || m.height != r.height) throw std::invalid_argument("frames differ in size");
    std::vector<bool> surface(r.pixels.size());
    for (size_t i = 0; i < surface.size(); ++i) surface[i] = m.pixels[i] != glm::dvec3(0.0);
    const weft::bench::MaskedError e = weft::bench::masked_error(m, r, surface);
    // Fine detail over the same pixels: the other frame's backdrop blacked out as the measured
    // frame's is, so that a silhouette's edge is the same edge in both.
    weft::Image d = detail_reference.empty() ? r : weft::read_exr(detail_reference);
    if (d.width != m.width || d.height != m.height) throw std::invalid_argument("detail reference differs in size");
    for (size_t i = 0; i < surface.size(); ++i)
      if (!surface[i]) d.pixels[i] = glm::dvec3(0.0);
    const weft::bench::DetailRatio detail = weft::bench::detail_ratio(m, d, limit);
    nlohmann::json j{{"relative_rmse", e.relative_rmse},
                     {"brightness_ratio", e.brightness_ratio},
                     {"surface_pixels", e.pixels},
                     {"detail_worst", detail.worst},
                     {"detail_worst_block", {detail.worst_column, detail.worst_row}},
                     {"detail_blocks_over", detail.over},
                     {"detail_blocks", detail.blocks}};
    std::cout << j.dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "frame_compare: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
