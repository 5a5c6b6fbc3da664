#include "bench/filament_peer/peer_report.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "bench/chart.h"
#include "bench/number_text.h"

namespace weft::peer {

using bench::fmt;

std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read");
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
      else if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) fields.emplace_back();
      else fields.back() += c;
    }
    if (quoted) throw std::runtime_error(file.string() + ": a quoted field runs past the end of its line");
    rows.push_back(std::move(fields));
  }
  return rows;
}

std::vector<WeftRow> read_weft_results(const std::filesystem::path& file) {
  const auto csv = read_csv(file);
  if (csv.empty()) throw std::runtime_error(file.string() + ": empty, not a weft bench results.csv");
  std::map<std::string, size_t> col;
  for (size_t i = 0; i < csv[0].size(); ++i) col[csv[0][i]] = i;
  for (const char* need : {"scene", "fabric", "env", "method", "speed_width", "speed_height", "ms_per_frame",
                           "relative_rmse"})
    if (!col.count(need)) throw std::runtime_error(file.string() + ": no column " + need + " (not a weft bench results.csv)");
  std::vector<WeftRow> rows;
  for (size_t r = 1; r < csv.size(); ++r) {
    const auto& f = csv[r];
    if (f.size() != csv[0].size()) throw std::runtime_error(file.string() + ": row " + std::to_string(r + 1) + " has " +
                                                            std::to_string(f.size()) + " fields, the header " +
                                                            std::to_string(csv[0].size()));
    WeftRow w;
    w.scene = f[col["scene"]], w.fabric = f[col["fabric"]], w.env = f[col["env"]], w.method = f[col["method"]];
    try {
      w.speed_width = std::stoi(f[col["speed_width"]]), w.speed_height = std::stoi(f[col["speed_height"]]);
      w.ms = std::stod(f[col["ms_per_frame"]]);
      const std::string& e = f[col["relative_rmse"]];
      w.relative_rmse = e.empty() ? -1.0 : std::stod(e);
    } catch (const std::logic_error&) {
      throw std::runtime_error(file.string() + ": row " + std::to_string(r + 1) + " has a number that does not parse");
    }
    rows.push_back(w);
  }
  return rows;
}

namespace {

bool same_case(const WeftRow& w, const PeerRow& p) { return w.scene == p.scene && w.fabric == p.fabric && w.env == p.env; }

// Weft's rows of the quoted rungs on the cases Filament ran.
std::vector<WeftRow> quoted(const std::vector<PeerRow>& rows, const std::vector<WeftRow>& weft) {
  std::vector<WeftRow> out;
  for (const auto& m : kQuotedRungs)
    for (const auto& p : rows)
      for (const auto& w : weft)
        if (w.method == m && same_case(w, p)) out.push_back(w);
  return out;
}

}  // namespace

void write_peer_csv(const std::filesystem::path& file, const std::vector<PeerRow>& rows) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(file.string() + ": cannot write");
  out << "scene,fabric,env,method,speed_width,speed_height,ms_per_frame,shipping_ms_per_frame,frames,width,height,"
         "relative_rmse,cloth_pixels\n";
  for (const auto& r : rows)
    out << r.scene << "," << r.fabric << "," << r.env << ",filament," << r.speed_width << "," << r.speed_height << ","
        << r.ms << "," << r.shipping_ms << "," << r.frames << "," << r.width << "," << r.height << "," << r.relative_rmse
        << "," << r.cloth_pixels << "\n";
  if (!out) throw std::runtime_error(file.string() + ": write failed");
}

void write_peer_chart(const std::filesystem::path& file, const std::vector<PeerRow>& rows,
                      const std::vector<WeftRow>& weft) {
  std::vector<bench::ChartPoint> points;
  for (const auto& w : quoted(rows, weft))
    if (w.relative_rmse > 0.0) points.push_back({w.method, w.ms, w.relative_rmse});
  for (const auto& r : rows) points.push_back({"filament", r.ms, r.relative_rmse});
  bench::write_chart_png(file, points, "Filament 1.9 (cloth, IBL) beside Weft's rungs");
}

void write_peer_report(const std::filesystem::path& file, const std::vector<PeerRow>& rows,
                       const std::vector<WeftRow>& weft, const std::string& command, const std::string& weft_source,
                       const std::vector<std::string>& notes) {
  std::ofstream md(file);
  if (!md) throw std::runtime_error(file.string() + ": cannot write");
  md << "# Filament beside Weft: the peer bench\n\nRegenerate: `" << command << "`\n\n";
  md << "Filament 1.9.25 (Debian's libfilament, OpenGL over GLX) draws each case's own triangles with its `cloth` "
        "shading model (tests/bench/filament_peer/filament_cloth.h maps the fabric), lit by an IBL that Filament's "
        "`cmgen` makes from the case's fitted SGs (the light the reference and Weft's rungs see), no shadows. "
        "Error: relative RMSE over the cloth pixels against the bench's reference, Filament's frame read back as "
        "linear radiance (no post-processing, exposure 1, IBL intensity 1, RGBA32F target). Speed: median frame, "
        "`Engine::flushAndWait` (glFinish) included, as `weft bench` times its rungs; 'shipping' is Filament's default "
        "frame (its tone mapper, FXAA, dithering, 8-bit swap chain).\n\n";
  const auto w = quoted(rows, weft);
  if (!w.empty()) md << "![chart](chart.png)\n\n";
  md << "| scene | fabric | map | method | ms/frame | shipping ms/frame | relative RMSE |\n|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    md << "| " << r.scene << " | " << r.fabric << " | " << r.env << " | **Filament** | " << fmt(r.ms) << " | "
       << fmt(r.shipping_ms) << " | " << fmt(r.relative_rmse) << " |\n";
    for (const auto& x : w)
      if (same_case(x, r))
        md << "| | | | " << x.method << " | " << fmt(x.ms) << (x.speed_width != r.speed_width || x.speed_height != r.speed_height
                                                                   ? " (at " + std::to_string(x.speed_width) + "x" +
                                                                         std::to_string(x.speed_height) + ")"
                                                                   : "")
           << " | | " << (x.relative_rmse >= 0 ? fmt(x.relative_rmse) : "n/a") << " |\n";
  }
  if (!w.empty()) {
    md << "\nGeometric means over the cases above, and each rung's time over Filament's (same cases):\n\n"
          "| method | ms/frame | relative RMSE | ms / Filament's ms |\n|---|---|---|---|\n";
    auto geo = [](const std::vector<double>& v) {
      double s = 0.0;
      for (double x : v) s += std::log(x);
      return v.empty() ? 0.0 : std::exp(s / double(v.size()));
    };
    std::vector<double> fm, fe;
    for (const auto& r : rows) fm.push_back(r.ms), fe.push_back(r.relative_rmse);
    md << "| **Filament** | " << fmt(geo(fm)) << " | " << fmt(geo(fe)) << " | 1 |\n";
    for (const auto& m : kQuotedRungs) {
      std::vector<double> ms, e, ratio;
      for (const auto& x : w)
        if (x.method == m) {
          ms.push_back(x.ms);
          if (x.relative_rmse > 0) e.push_back(x.relative_rmse);
          for (const auto& r : rows)
            if (same_case(x, r) && r.ms > 0) ratio.push_back(x.ms / r.ms);
        }
      if (!ms.empty())
        md << "| " << m << " | " << fmt(geo(ms)) << " | " << (e.empty() ? "n/a" : fmt(geo(e))) << " | "
           << fmt(geo(ratio)) << " |\n";
    }
  }
  md << "\n";
  if (!weft_source.empty()) md << "Weft's rows: " << weft_source << ".\n\n";
  for (const auto& n : notes) md << n << "\n\n";
  md << "Images (`images/`): each case's Filament frame and the reference, at the accuracy size, with one exposure.\n";
  if (!md) throw std::runtime_error(file.string() + ": write failed");
}

}  // namespace weft::peer
