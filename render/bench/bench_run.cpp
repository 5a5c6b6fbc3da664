#include "bench/bench_run.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bake/selection/scene_selection.h"
#include "bench/bench_case.h"
#include "bench/bench_results.h"
#include "bench/knob_sweeps.h"
#include "bench/ladder.h"
#include "bench/number_text.h"
#include "bench/reference_set.h"
#include "bench/report.h"
#include "bench/row_measure.h"
#include "bench/sky_sweep.h"
#include "bench/stability.h"
#include "bench/stopwatch.h"
#include "bench/table_bakes.h"
#include "gpu/scene_renderer.h"
#include "methods/registry.h"
#include "scene/mesh_subdivision.h"
#include "scene/mesh_vertex_order.h"

namespace weft::bench {

namespace {

// The row of a weighting-table method (iwasaki or iwasaki_vertex) with the setting `weft bake
// --target-error` picks for it (bake/selection/scene_selection.h, the method held fixed), next to the
// paper-default row of the same case; its views' references cached beside the bench's.
Row target_error_row(const BenchOptions& a, const Case& c, const LadderEntry& m, RowMeasure& measure,
                     const std::filesystem::path& cache) {
  SceneSelectionOptions o;
  o.target_error = a.target_error;
  o.cache = cache / "selection-views";
  o.grid = a.bake_grid;
  o.knobs.methods = {m.name};
  if (a.quick) o.views.width = 64, o.views.height = 48, o.views.sg_grid = 4, o.views.tangent_samples = 8;
  std::map<std::string, std::string> texts;
  for (const auto& [name, f] : c.fabrics) {
    std::ifstream in(fabric_file(name, a.assets / "fabrics"));
    std::ostringstream text;
    text << in.rdbuf();
    texts[name] = text.str();
  }
  std::cerr << "weft bench: selecting " << m.name << " settings for " << c.tag << " at target " << fmt(a.target_error)
            << " ..." << std::flush;
  const SceneSelection sel = select_scene_settings(c.scene, c.fabrics, texts, c.sgs, o);
  std::cerr << " " << fmt(sel.seconds) << " s: " << sel.description << "\n";
  const Scene drawn = refine_and_order_meshes(c.scene, sel.subdivision);  // the meshes the search baked
  Row r = measure.measure(c, m, target_label(m.name, a.target_error), m.name + "_target",
                          std::make_shared<const ShadingData>(sel.data), &drawn);
  r.setting = sel.description, r.sg_count = sel.chosen.sg_count, r.subdivision = sel.subdivision;
  r.note = "scene_selection.h at target " + fmt(a.target_error) + ": " + sel.description + ", views' error " +
           fmt(sel.chosen.error) + (sel.reached ? "" : " (unreachable: closest)");
  return r;
}

// The row of a per-vertex method on the case's cloth refined `levels` (scene/mesh_subdivision.h):
// the paper-default tables, the cloth's visibility baked on the refined vertices at the paper's
// settings (floors and occluders keep theirs), against the case's reference.
Row subdivided_row(const Case& c, const LadderEntry& m, int levels, TableBakes& bakes, RowMeasure& measure) {
  const Scene drawn = refine_cloth_meshes(c.scene, levels);
  double bake_s = 0.0;
  const auto bundle = bakes.subdivided(m.name, c.scene, drawn, levels, c.fabrics, bake_s);
  Row r = measure.measure(c, m, m.name + " (subdivision " + std::to_string(levels) + ")",
                          m.name + "_sub" + std::to_string(levels), bundle, &drawn);
  r.subdivision = levels, r.visibility_bake_s = bake_s;
  r.note = "cloth meshes midpoint-subdivided " + std::to_string(levels) + "x, their visibility baked in " +
           fmt(bake_s) + " s";
  return r;
}

// Speed and accuracy rows: every method on every scene × fabric × environment (with the
// target-error row after each iwasaki row, and the subdivided rows after each per-vertex one).
void ladder_rows(const BenchOptions& a, const std::vector<LadderEntry>& run, TableBakes& bakes, RowMeasure& measure,
                 const std::filesystem::path& cache, BenchResults& res) {
  for (const auto& scene_name : a.scenes) {
    for (const auto& fabric_arg : a.fabrics) {
      for (const auto& env_arg : a.envs) {
        const Case c = make_case(a, scene_name, fabric_arg, env_arg);
        if (c.shadow && res.thin_occluder_case.empty()) res.thin_occluder_case = thin_occluder_text(c);
        for (const auto& m : run) {
          if (!m.scenes.empty() && !m.scenes.count(scene_name)) continue;
          res.rows.push_back(measure.measure(c, m, m.name, m.name, bakes.tables_for(m.name, c.scene, c.fabrics)));
          if (const auto& method = methods::method(m.name);
              method.shading == methods::Shading::per_vertex && method.reads_weighting_tables())
            for (int levels : a.subdivide) res.rows.push_back(subdivided_row(c, m, levels, bakes, measure));
          if ((m.name == "iwasaki" || m.name == "iwasaki_vertex") && a.target_error > 0)
            res.rows.push_back(target_error_row(a, c, m, measure, cache));
        }
      }
    }
  }
}

// Stability table: every CPU method × stress case, against the canonical model.
std::vector<StabilityCell> stability_cells(const BenchOptions& a) {
  std::vector<StabilityCell> cells;
  if (a.no_stability || a.stress_points <= 0) return cells;
  const auto cases = stress_cases(a.assets / "fabrics", a.stress_points);
  std::vector<std::vector<glm::dvec3>> refs;
  for (const auto& c : cases) refs.push_back(stress_reference(c));
  for (const auto& m : cpu_methods())
    for (size_t i = 0; i < cases.size(); ++i)
      cells.push_back({m.name, cases[i].name, cases[i].notes, run_stress(m, cases[i], &refs[i])});
  return cells;
}

}  // namespace

int run_bench(BenchOptions a) {
  apply_quick(a);
  apply_sweep(a);
  validate(a);
  const auto available = methods::method_names();
  const bool has_iwasaki = std::find(available.begin(), available.end(), "iwasaki") != available.end();
  const LadderRun ladder_run = select_methods(available, a.methods);
  const auto& run = ladder_run.run;

  BenchResults res;
  res.missing = ladder_run.missing;
  res.run_iwasaki = std::any_of(run.begin(), run.end(), [](const LadderEntry& e) { return e.name == "iwasaki"; });
  res.target_label = target_label("iwasaki", a.target_error);

  const std::filesystem::path out(a.out);
  const std::filesystem::path cache = a.cache.empty() ? out / "reference-cache" : std::filesystem::path(a.cache);
  std::filesystem::create_directories(out / "images");
  const auto t_start = std::chrono::steady_clock::now();
  TableBakes bakes(a);
  ReferenceSet references(a, cache);
  RowMeasure measure(a, out, references);
  res.paper_sdf_resolution = bakes.paper_options().visibility.resolution;

  ladder_rows(a, run, bakes, measure, cache, res);
  res.renderer = measure.renderer();
  sweep_sg_counts(a, run, bakes, references, out, res);
  sweep_bake_knobs(a, has_iwasaki, bakes, references, out, res);
  res.stability = stability_cells(a);
  res.seconds = seconds_since(t_start);
  res.reference_seconds = references.render_seconds();
  res.references_rendered = references.rendered();
  res.references_cached = references.cached();
  res.references = references.records();

  write_results_csv(out, a, res);
  write_chart(out, a, res);
  write_report_md(out, a, res);
  write_sky_sweep(out, a, res);
  std::cout << "{\"out\":\"" << a.out << "\",\"rows\":" << res.rows.size() << ",\"seconds\":" << fmt(res.seconds, 4)
            << ",\"csv\":\"" << (out / "results.csv").string() << "\",\"chart\":\"" << (out / "chart.png").string()
            << "\",\"report\":\"" << (out / "report.md").string() << "\"}\n";
  return 0;
}

}  // namespace weft::bench
