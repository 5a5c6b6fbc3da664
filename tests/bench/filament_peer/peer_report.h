#pragma once
// The peer bench's outputs: results.csv (Filament's rows), chart.png (Filament's marker on
// the bench's speed/accuracy chart beside Weft's rungs on the same cases) and README.md
// (the tables), from Filament's rows and Weft's rows read from a `weft bench` results.csv.
#include <filesystem>
#include <string>
#include <vector>

namespace weft::peer {

struct PeerRow {
  std::string scene, fabric, env;
  int speed_width = 0, speed_height = 0, frames = 0, width = 0, height = 0;
  double ms = 0.0;           // linear frame (filament_frame.h)
  double shipping_ms = 0.0;  // Filament's default post-processing, 8-bit swap chain
  double relative_rmse = 0.0;
  size_t cloth_pixels = 0;
  std::string image, reference_image;  // under the output folder
};

// One row of a `weft bench` results.csv: the columns the peer's tables quote.
struct WeftRow {
  std::string scene, fabric, env, method;
  int speed_width = 0, speed_height = 0;
  double ms = 0.0, relative_rmse = -1.0;  // −1: not measured
};

// A CSV file's fields, quoted fields as RFC 4180 has them (the renderer column holds commas).
// Hand-written: two dozen lines, where a CSV library would be a new dependency for one file.
std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& file);

// Throws std::runtime_error naming the file when it cannot be read or lacks a needed column.
std::vector<WeftRow> read_weft_results(const std::filesystem::path& file);

// The rungs quoted beside Filament, in table order: the kiosk's default, its per-vertex
// siblings, and the glTF viewers' sheen.
inline const std::vector<std::string> kQuotedRungs{"iwasaki_vertex_quadrature", "iwasaki_vertex",
                                                   "iwasaki_vertex_mask", "sheen"};

void write_peer_csv(const std::filesystem::path& file, const std::vector<PeerRow>& rows);
void write_peer_chart(const std::filesystem::path& file, const std::vector<PeerRow>& rows,
                      const std::vector<WeftRow>& weft);
// `command`: the line that regenerates the run; `weft_source`: where Weft's rows came from
// ("" when none were given); `notes`: lines for the end of the report.
void write_peer_report(const std::filesystem::path& file, const std::vector<PeerRow>& rows,
                       const std::vector<WeftRow>& weft, const std::string& command, const std::string& weft_source,
                       const std::vector<std::string>& notes);

}  // namespace weft::peer
