#pragma once
// The speed/accuracy chart, drawn into an RGB raster (lines, discs, a 3×5 pixel font) and
// written with libpng: x = ms/frame, y = relative RMSE over cloth pixels, both log; one large
// marker per method (geometric mean over the cases it ran), a small dot per case, and the
// Pareto front (methods no other method beats in both) joined by a line.
#include <filesystem>
#include <string>
#include <vector>

namespace weft::bench {

struct ChartPoint {
  std::string method;
  double ms = 0.0;
  double relative_rmse = 0.0;
};

struct ChartMarker {
  std::string method;
  double ms = 0.0, relative_rmse = 0.0;  // geometric means
  bool pareto = false;
};

// Per method: geometric means of the points (non-positive values skipped), in first-seen
// order, with the Pareto flags set.
std::vector<ChartMarker> chart_markers(const std::vector<ChartPoint>& points);

// Throws std::runtime_error if the file cannot be written.
void write_chart_png(const std::filesystem::path& file, const std::vector<ChartPoint>& points,
                     const std::string& title);

}  // namespace weft::bench
