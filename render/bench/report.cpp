#include "bench/report.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "bench/bench_case.h"
#include "bench/number_text.h"
#include "bench/ladder.h"
#include "bench/stability.h"
#include "files/atomic_file.h"

namespace weft::bench {

namespace {

// Every row with a measured error, for the chart and its table of markers.
std::vector<ChartPoint> chart_points(const std::vector<Row>& rows) {
  std::vector<ChartPoint> points;
  for (const auto& r : rows)
    if (r.rmse > 0) points.push_back({r.method, r.ms, r.rmse});
  return points;
}


}  // namespace

std::string reference_samples_text(const BenchOptions& a) {
  if (a.reference_tolerance <= 0.0) return std::to_string(a.tangent_samples) + " tangent samples per thread, fixed";
  return "tangent samples per thread from " + std::to_string(a.tangent_samples) + ", doubled up to " +
         std::to_string(kReferenceTangentCap) + " until the cloth changes by at most " +
         fmt(100.0 * a.reference_tolerance) + " % (each case's in results.csv, reference_tangent_samples)";
}

namespace {

// Header, the chart with its table of markers, and every row.
void overview(std::ostream& md, const BenchOptions& a, const BenchResults& res) {
  const auto& rows = res.rows;
  const auto& renderer = res.renderer;
  const double total = res.seconds, reference_seconds = res.reference_seconds;
  const int references_rendered = res.references_rendered, references_cached = res.references_cached;
  const auto markers = chart_markers(chart_points(rows));
  md << "# Weft bench: speed against accuracy\n\n";
  md << "Regenerate: `" << command_line(a) << "` (" << fmt(total, 4)
     << " s this run; " << references_rendered << " reference renders, " << fmt(reference_seconds, 4) << " s, "
     << references_cached << " from the cache).\n\n";
  md << "GL renderer: `" << renderer << "`. Speed: median of " << a.speed_frames << " frames after one warm-up frame, "
     << "glFinish included, at " << a.speed_width << "x" << a.speed_height << ". Accuracy: relative RMSE "
     << "`sqrt(mean((x-r)^2))/mean(r)` over the cloth pixels at " << a.width << "x" << a.height << " against `reference` "
     << "under the same " << a.sg_count << " fitted SGs (SG grid " << a.sg_grid << "x" << 2 * a.sg_grid << ", "
     << reference_samples_text(a) << "). Times on llvmpipe: compare ratios within one run.\n\n";
  md << "![chart](chart.png)\n\n";
  md << "| method | ms/frame (geo. mean) | relative RMSE (geo. mean) | Pareto front |\n|---|---|---|---|\n";
  for (const auto& k : markers)
    md << "| " << k.method << " | " << fmt(k.ms) << " | " << fmt(k.relative_rmse) << " | " << (k.pareto ? "yes" : "")
       << " |\n";
  md << "\n## Every case (results.csv)\n\nFloor & occluders: the same relative RMSE over the Lambertian pixels, and their "
        "brightness against the reference (mean(x)/mean(r)); they are shaded per vertex with the bundle's visibility "
        "(methods/lambert_visibility.h) under the methods that read a bundle (iwasaki, iwasaki_vertex, mizutani); the "
        "others are drawn here without one, so their floors are unshadowed: the column compares the two.\n\n"
        "| scene | fabric | env | method | ms/frame | relative RMSE | floor & occluders: RMSE / brightness | note |\n"
        "|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    md << "| " << r.scene << " | " << r.fabric << " | " << r.env << " | " << r.method << " | " << fmt(r.ms) << " | "
       << (r.rmse >= 0 ? fmt(r.rmse) : "n/a") << " | "
       << (r.lambert_rmse >= 0 ? fmt(r.lambert_rmse) + " / " + fmt(r.lambert_ratio) : "n/a") << " | " << r.note << " |\n";
}

// The target-error point against the paper default, case by case.
void target_error_section(std::ostream& md, const BenchOptions& a, const BenchResults& res) {
  const auto& rows = res.rows;
  const bool run_iwasaki = res.run_iwasaki;
  // The target-error point against the paper default, case by case, from the numbers above.
  if (run_iwasaki && a.target_error > 0) {
    md << "\n## `weft bake --target-error " << fmt(a.target_error) << "` against the paper's settings\n\n"
       << "`METHOD (target " << fmt(a.target_error) << ")`: the setting `weft bake --target-error` picks for the method "
       << "(bake/selection/scene_selection.h: tangent samples, λ levels, SVD error, SDF resolution, PCA error, searched from the "
          "paper's setting by measuring the image error on the scene's views, 160x120, against the reference; grids as the "
          "paper row). Cost: ms/frame and bundle bytes (tables + visibility PCA). The RMSE here is on the bench's own view "
          "and size, which the search did not measure.\n\n"
       << "| case | paper: ms | target: ms | paper: RMSE | target: RMSE | paper: bytes | target: bytes | verdict |\n"
       << "|---|---|---|---|---|---|---|---|\n";
    for (const auto& p : rows) {
      if (p.method != "iwasaki" && p.method != "iwasaki_vertex") continue;
      for (const auto& t : rows) {
        if (t.method != target_label(p.method, a.target_error) || t.scene != p.scene || t.fabric != p.fabric || t.env != p.env) continue;
        // "Same" error: within 2 % of the paper row's (the llvmpipe images are deterministic;
        // this only forgives rounding-level differences). Speed: within 5 % counts as equal.
        const bool error_ok = t.rmse <= 1.02 * p.rmse;
        const bool faster = t.ms < 0.95 * p.ms, slower = t.ms > 1.05 * p.ms;
        const bool smaller = t.bundle_bytes < p.bundle_bytes;
        std::string verdict;
        if (error_ok && (faster || smaller) && !slower)
          verdict = "yes: same or better error at lower cost";
        else if (!error_ok)
          verdict = "no: error " + fmt(t.rmse / p.rmse) + "x the paper's";
        else
          verdict = "no: error as good, but not cheaper (" + std::string(slower ? "slower" : "same speed") + ", " +
                    (smaller ? "smaller" : "not smaller") + ")";
        md << "| " << p.scene << " / " << p.fabric << " / " << p.env << " / " << p.method << " | " << fmt(p.ms) << " | " << fmt(t.ms) << " | "
           << fmt(p.rmse) << " | " << fmt(t.rmse) << " | " << p.bundle_bytes << " | " << t.bundle_bytes << " | " << verdict
           << " |\n";
        md << "| | tables: " << p.tables << " | tables: " << t.tables << " | | | | | |\n";
      }
    }
  }
}

// Each row's image beside the reference and the error map.
void images_section(std::ostream& md, const BenchOptions& a, const BenchResults& res) {
  const auto& rows = res.rows;
  md << "\n## Images (method | reference | error: black 0, red 0.5, yellow ≥ 1 of the mean cloth radiance)\n\n";
  md << "| case | method | reference | error |\n|---|---|---|---|\n";
  for (const auto& r : rows)
    md << "| " << r.scene << " / " << r.fabric << " / " << r.env << " / " << r.method << " | ![](" << r.image
       << ") | ![](" << r.reference_image << ") | " << (r.error_image.empty() ? "n/a" : "![](" + r.error_image + ")")
       << " |\n";
}

// The see-through methods (those measured against the thin-layer reference: thin, sheer,
// sheer_vertex) on each of their cases in one row: the reference, then each method's image.
void see_through_section(std::ostream& md, const BenchResults& res) {
  std::vector<std::string> cases;
  std::map<std::string, std::vector<const Row*>> by_case;
  for (const auto& r : res.rows) {
    if (!thin_reference(r.method)) continue;
    const std::string key = r.scene + " / " + r.fabric + " / " + r.env;
    if (!by_case.count(key)) cases.push_back(key);
    by_case[key].push_back(&r);
  }
  if (cases.empty()) return;
  md << "\n## See-through cloth side by side (thin-layer reference, then each method; relative RMSE)\n\n";
  for (const auto& key : cases) {
    const auto& rows = by_case.at(key);
    md << "**" << key << "**\n\n| reference |";
    for (const Row* r : rows) md << " " << r->method << " (" << (r->rmse >= 0 ? fmt(r->rmse) : "n/a") << ") |";
    md << "\n|---|";
    for (size_t i = 0; i < rows.size(); ++i) md << "---|";
    md << "\n| ![](" << rows.front()->reference_image << ") |";
    for (const Row* r : rows) md << " ![](" << r->image << ") |";
    md << "\n\n";
  }
}

// The cost-knob sweeps: SG count, then each of iwasaki's bake knobs.
void sweep_sections(std::ostream& md, const BenchOptions& a, const BenchResults& res) {
  const auto& sweep = res.sweep;
  const auto& sweep_case = res.sweep_case;
  const auto& knob_sweeps = res.knob_sweeps;
  const auto& knob_case = res.knob_case;
  const auto& knob_default = res.knob_default;
  if (!sweep.empty()) {
    md << "\n## Cost knob: SG count (sweep_sg_count.csv)\n\n" << sweep_case << ": K SGs fitted to the map, "
       << "relative RMSE against the reference lit by the map itself (the fit's error included), ms/frame at "
       << a.speed_width << "x" << a.speed_height << " (median of 5 frames).\n\n| method | K | ms/frame | relative RMSE |\n"
       << "|---|---|---|---|\n";
    for (const auto& r : sweep)
      md << "| " << r.method << " | " << r.sg_count << " | " << fmt(r.ms) << " | " << fmt(r.rmse) << " |\n";
  }
  for (const auto& ks : knob_sweeps) {
    md << "\n## Cost knob: iwasaki " << ks.knob << " (" << ks.file << ")\n\n";
    if (!ks.skipped.empty()) {
      md << "Not measured: " << ks.skipped << ".\n";
      continue;
    }
    md << knob_case << ", " << a.sg_count << " SGs: one knob changed from the paper-default bundle (the rest as the `iwasaki` "
       << "row: tables grid " << (a.bake_grid > 0 ? a.bake_grid : 48) << ", SDF " << res.paper_sdf_resolution
       << "², the paper's tangent samples, SVD error 0.01), each point a fresh in-memory bake; relative RMSE against the "
       << "same reference as the main rows, ms/frame at " << a.speed_width << "x" << a.speed_height
       << " (median of 5 frames; llvmpipe times move by tens of % under load: compare within one run); bytes as "
          "stored in the bundle (tables: U and V of every truncated T; visibility: PCA; the runtime reconstructs d from "
          "the PCA only at the SG axes, so GPU memory does not grow with the SDF resolution).\n\n"
       << "| " << ks.knob << " | ms/frame | relative RMSE | table bytes | visibility bytes | bake s | tables |\n"
       << "|---|---|---|---|---|---|---|\n";
    auto line = [&](const KnobRow& r, bool bake) {
      md << "| " << r.value << " | " << fmt(r.ms) << " | " << fmt(r.rmse) << " | " << r.table_bytes << " | "
         << r.visibility_bytes << " | " << (bake ? fmt(r.bake_s) : "") << " | " << r.tables
         << " |\n";
    };
    KnobRow d = knob_default;
    d.value = "paper default (" + ks.default_value + ")";
    line(d, false);
    for (const auto& r : ks.rows) line(r, true);
  }
}

// The stability table: CPU methods × point-based stress cases.
void stability_section(std::ostream& md, const BenchOptions& a, const BenchResults& res) {
  const auto& stability = res.stability;
  md << "\n## Stability: method × stress case → error\n\n";
  if (stability.empty()) {
    md << "Not run (--no-stability).\n";
  } else {
    md << "C++ evaluation of each method at " << a.stress_points << " points per case (render/bench/stability.h), "
       << "relative RMSE against the canonical model by quadrature (1 % tolerance) (for `thin`: (1-α)·canonical + the thin layer "
       << "integrated exactly). iwasaki and mizutani read tables baked for the stress fabrics at grid " << kStressTableGrid
       << " with the paper's tangent samples (iwasaki without visibility), so their error includes those few samples "
          "against the reference's 16. NaN/Inf/negative counts must be 0 (tests/bench/method_stability_test.cpp asserts it at "
       << "150 points per case).\n\n| method |";
    std::vector<std::string> case_names;
    for (const auto& c : stability)
      if (std::find(case_names.begin(), case_names.end(), c.stress) == case_names.end()) case_names.push_back(c.stress);
    for (const auto& c : case_names) md << " " << c << " |";
    md << "\n|---|";
    for (size_t i = 0; i < case_names.size(); ++i) md << "---|";
    std::string current;
    for (const auto& c : stability) {
      if (c.method != current) md << "\n| " << c.method << " |", current = c.method;
      std::string cell;
      if (c.r.non_finite || c.r.negative)
        cell = "**" + std::to_string(c.r.non_finite) + " NaN/Inf, " + std::to_string(c.r.negative) + " negative** ";
      if (c.r.measured && c.r.reference_mean > 0) cell += fmt(c.r.relative_rmse, 2);
      else if (c.r.measured) cell += c.r.max_abs == 0.0 ? "exact 0" : "nonzero in the dark: " + fmt(c.r.max_abs, 2);
      md << " " << cell << " |";
    }
    md << "\n\nCases: ";
    for (size_t i = 0; i < stability.size(); ++i)
      if (stability[i].method == stability[0].method) md << "`" << stability[i].stress << "`: " << stability[i].notes << ". ";
    md << "\n";
  }
}

// The thin-occluder table, from the teapot images.
void thin_occluder_section(std::ostream& md, const BenchOptions& a, const BenchResults& res) {
  const auto& rows = res.rows;
  const auto& thin_occluder_case = res.thin_occluder_case;
  // The thin-occluder case: the point-based cases above have no scene, hence no visibility; this
  // table is read off the ladder's images of the teapot scene.
  md << "\n## Stability: thin occluder (" << kThinOccluderScene << ", image)\n\n";
  std::vector<const Row*> thin_rows;
  for (const auto& r : rows)
    if (r.scene == kThinOccluderScene && r.shadow_pixels > 0) thin_rows.push_back(&r);
  if (thin_rows.empty()) {
    md << "Not measured: `" << kThinOccluderScene << "` is not among this run's --scenes (or no cloth pixel of it is "
       << "in the sun's shadow).\n";
  } else {
    md << "The point-based stress cases above evaluate single surface points with no scene around them, so they test no "
       << "visibility at all. This table comes from the `" << kThinOccluderScene << "` images of the ladder (" << a.width
       << "x" << a.height << ", against the reference): the Utah teapot on cloth under the sharp sun of " << thin_occluder_case
       << ". Only the methods marked with visibility shade with it (the linearised SDF per SG, baked for the "
       << "scene); every other method has none (each SG lights every cloth point, sgpoint included), so the missing "
       << "shadows of the spout, the handle and the body count as their error here: that is what this case measures. "
       << "Shadow: cloth pixels whose point sees the sun's axis blocked, by the body as well as the spout and the handle "
       << "(one Embree ray per pixel, bench/shadow_mask.h); "
       << "beside: sunlit cloth pixels within 3 px of the shadow. Relative RMSE in the shadow is normalised by the "
       << "reference's mean there; brightness = mean(method)/mean(reference) over those pixels: in the shadow, > 1 means "
       << "the shadow is too light (missing, or spread thin over a wider area); beside it, < 1 means shadow spread into "
       << "the sunlit cloth.\n\n"
       << "| fabric / env | method | visibility | relative RMSE (whole cloth) | relative RMSE (in the shadow) | "
       << "brightness in the shadow | brightness beside it |\n|---|---|---|---|---|---|---|\n";
    for (const Row* r : thin_rows)
      md << "| " << r->fabric << " / " << r->env << " | " << r->method << " | " << (r->visibility ? "baked SDF" : "none") << " | " << fmt(r->rmse) << " | "
         << fmt(r->shadow_rmse) << " | " << fmt(r->shadow_ratio) << " | " << (r->band_ratio >= 0 ? fmt(r->band_ratio) : "n/a")
         << " |\n";
  }
}

// What this run did not measure.
void missing_section(std::ostream& md, const BenchOptions& a, const BenchResults& res) {
  const bool run_iwasaki = res.run_iwasaki;
  const auto& knob_sweeps = res.knob_sweeps;
  const auto& missing = res.missing;
  md << "\n## Missing\n\n";
  for (const auto& m : missing) md << "- `" << m << "`: not in the GPU runtime of this build (`weft render --method` lists what is).\n";
  if (a.sweep_sg_counts.empty() && knob_sweeps.empty())
    md << "- Cost-knob sweeps: none asked for this run (`--sweep-sg-counts`, `--sweep-tangent-samples`, "
          "`--sweep-svd-error`, `--sweep-sdf-resolution`).\n";
  if (a.target_error <= 0 || !run_iwasaki)
    md << "- The `weft bake --target-error` point: not measured this run (needs `iwasaki` and `--target-error` > 0).\n";
  md << "- The SVD knob is swept as its error target (ranks follow from it per table; the tables column gives the mean); "
        "the κ table and the λ levels are not swept; the sweeps are tables and CSVs, not drawn on the chart. The stability table's iwasaki runs without visibility, on tables of "
        "grid " << kStressTableGrid << " (not 48) with the paper's tangent samples; mizutani likewise.\n";
}

}  // namespace

void write_results_csv(const std::filesystem::path& out, const BenchOptions& a, const BenchResults& res) {
  const auto& rows = res.rows;
  const auto& renderer = res.renderer;
  std::ostringstream csv;
  csv << "scene,fabric,env,method,speed_width,speed_height,ms_per_frame,frames,width,height,relative_rmse,cloth_pixels,"
         "renderer,note,bundle_bytes,shadow_pixels,shadow_relative_rmse,shadow_brightness_ratio,band_brightness_ratio,"
         "lambert_relative_rmse,lambert_brightness_ratio,setting,sg_count,subdivision,cloth_mesh_bytes,"
         "visibility_bake_seconds,reference_tangent_samples\n";
  for (const auto& r : rows)
    csv << r.scene << "," << r.fabric << "," << (r.env.find(',') == std::string::npos ? r.env : "\"" + r.env + "\"") << "," << r.method << "," << a.speed_width << "," << a.speed_height
        << "," << fmt(r.ms, 6) << "," << r.frames << "," << a.width << "," << a.height << ","
        << (r.rmse >= 0 ? fmt(r.rmse, 6) : "") << "," << r.cloth_pixels << ",\"" << renderer << "\",\"" << r.note
        << "\"," << (r.bundle_bytes ? std::to_string(r.bundle_bytes) : "") << ","
        << (r.shadow_pixels ? std::to_string(r.shadow_pixels) : "") << "," << (r.shadow_rmse >= 0 ? fmt(r.shadow_rmse, 6) : "")
        << "," << (r.shadow_ratio >= 0 ? fmt(r.shadow_ratio, 6) : "") << ","
        << (r.band_ratio >= 0 ? fmt(r.band_ratio, 6) : "") << "," << (r.lambert_rmse >= 0 ? fmt(r.lambert_rmse, 6) : "")
        << "," << (r.lambert_ratio >= 0 ? fmt(r.lambert_ratio, 6) : "") << ",\"" << r.setting << "\","
        << (r.sg_count ? std::to_string(r.sg_count) : "") << ","
        << (r.subdivision >= 0 ? std::to_string(r.subdivision) : "") << ","
        << (r.cloth_mesh_bytes ? std::to_string(r.cloth_mesh_bytes) : "") << ","
        << (r.visibility_bake_s >= 0 ? fmt(r.visibility_bake_s, 4) : "") << ","
        << (r.reference_tangent_samples ? std::to_string(r.reference_tangent_samples) : "") << "\n";
  write_file_atomically(out / "results.csv", csv.view());
}

void write_chart(const std::filesystem::path& out, const BenchOptions& a, const BenchResults& res) {
  write_chart_png(out / "chart.png", chart_points(res.rows), "WEFT BENCH " + std::to_string(a.speed_width) + "X" +
                                                                std::to_string(a.speed_height) + " (" + res.renderer + ")");
}

void write_sg_sweep_csv(const std::filesystem::path& file, const std::vector<SweepRow>& sweep) {
  std::ostringstream csv;
  csv << "method,sg_count,ms_per_frame,relative_rmse_vs_map\n";
  for (const auto& r : sweep) csv << r.method << "," << r.sg_count << "," << fmt(r.ms, 6) << "," << fmt(r.rmse, 6) << "\n";
  write_file_atomically(file, csv.view());
}

void write_knob_sweep_csv(const std::filesystem::path& file, const KnobSweep& ks) {
  std::ostringstream csv;
  csv << "knob,value,ms_per_frame,relative_rmse,table_bytes,visibility_bytes,bake_seconds,tables\n";
  for (const auto& r : ks.rows)
    csv << ks.knob << "," << r.value << "," << fmt(r.ms, 6) << "," << fmt(r.rmse, 6) << "," << r.table_bytes << ","
        << r.visibility_bytes << "," << fmt(r.bake_s, 4) << ",\"" << r.tables << "\"\n";
  write_file_atomically(file, csv.view());
}

void write_report_md(const std::filesystem::path& out, const BenchOptions& a, const BenchResults& res) {
  std::ostringstream md;
  overview(md, a, res);
  target_error_section(md, a, res);
  images_section(md, a, res);
  see_through_section(md, res);
  sweep_sections(md, a, res);
  stability_section(md, a, res);
  thin_occluder_section(md, a, res);
  missing_section(md, a, res);
  write_file_atomically(out / "report.md", md.view());
}

}  // namespace weft::bench
