#include "bench/knob_sweeps.h"

#include <chrono>
#include <functional>
#include <iostream>

#include "bake/tables/bake_selection.h"
#include "bench/bench_case.h"
#include "measure/image_metrics.h"
#include "bench/number_text.h"
#include "bench/report.h"
#include "bench/stopwatch.h"
#include "bench/table_stats.h"
#include "frame/frame_render.h"
#include "lighting/env_map.h"
#include "lighting/sg_fit.h"
#include "scene/scene_fabrics.h"
#include "scene/scene_file.h"

namespace weft::bench {

void sweep_sg_counts(const BenchOptions& a, const std::vector<LadderEntry>& run, TableBakes& bakes,
                     ReferenceSet& references, const std::filesystem::path& out, BenchResults& results) {
  if (a.sweep_sg_counts.empty()) return;
  const Scene s = load_scene_named(a.scenes.front(), a.assets);
  const std::map<std::string, Fabric> fabrics = load_scene_fabrics(s, a.assets / "fabrics");
  const auto env_file = env_map_file(s.environment, a.assets / "envmaps");
  auto map = std::make_shared<EnvMap>(load_env_map(env_file, NonFinitePolicy::clamp, nullptr));
  results.sweep_case = s.name + " / " + fabrics.begin()->first + " / " + s.environment + " (map-lit reference, 128x64 cells)";
  const CachedReference ref = references.map_lit(a.scenes.front(), s, fabrics, env_file, map);
  for (int k : a.sweep_sg_counts) {
    SgFitOptions fit;
    fit.count = k;
    const SgLighting sgs = fit_sgs(*map, fit);
    for (const auto& m : run) {
      if (!m.scenes.empty() && !m.scenes.count(s.name)) continue;
      if (m.thin_reference) continue;  // the map-lit reference has opaque cloth
      SweepRow r{m.name, k, 0.0, 0.0};
      r.ms = render_gpu_frame(s, fabrics, sgs, m.name, a.speed_width, a.speed_height, 5, bakes.tables_for(m.name, s, fabrics)).median_ms;
      const GpuFrame acc = render_gpu_frame(s, fabrics, sgs, m.name, a.width, a.height, 0, bakes.tables_for(m.name, s, fabrics));
      r.rmse = cloth_error(acc.image, ref.image, ref.kinds).relative_rmse;
      std::cerr << "weft bench: sweep " << m.name << " K=" << k << ": " << fmt(r.ms) << " ms, relative RMSE "
                << fmt(r.rmse) << "\n";
      results.sweep.push_back(r);
    }
  }
  write_sg_sweep_csv(out / "sweep_sg_count.csv", results.sweep);
}

namespace {

std::vector<std::string> texts(const auto& v) {
  std::vector<std::string> t;
  for (const auto& x : v) t.push_back(fmt(double(x), 4));
  return t;
}

}  // namespace

// Each point is a fresh in-memory bake of the changed half of the bundle (tables, or
// visibility + κ), the other half shared with the paper-default bundle.
void sweep_bake_knobs(const BenchOptions& a, bool has_iwasaki, TableBakes& bakes, ReferenceSet& references,
                      const std::filesystem::path& out, BenchResults& results) {
  if (a.sweep_tangent_samples.empty() && a.sweep_svd_errors.empty() && a.sweep_sdf_resolutions.empty() &&
      a.sweep_sdf_supersamples.empty())
    return;
  const Case c = make_case(a, a.scenes.front(), "scene", "scene");
  results.knob_case = c.scene_name + " / " + c.fabric_label + " / " + c.env;
  KnobRow& knob_default = results.knob_default;
  std::shared_ptr<const ShadingData> base;
  if (has_iwasaki) {
    base = bakes.tables_for("iwasaki", c.scene, c.fabrics);
    knob_default.value = "paper default";
    knob_default.table_bytes = table_bytes(*base), knob_default.visibility_bytes = visibility_bytes(*base);
    knob_default.tables = tables_summary(*base);
    const CachedReference& ref = references.sg_lit(c, false);
    knob_default.ms =
        render_gpu_frame(c.scene, c.fabrics, c.sgs, "iwasaki", a.speed_width, a.speed_height, 5, base).median_ms;
    const GpuFrame acc = render_gpu_frame(c.scene, c.fabrics, c.sgs, "iwasaki", a.width, a.height, 0, base);
    knob_default.rmse = cloth_error(acc.image, ref.image, ref.kinds).relative_rmse;
  }
  auto knob_sweep = [&](const std::string& knob, const std::string& file, const std::string& default_value,
                        const std::vector<std::string>& values, const std::function<void(size_t, ShadingDataBakeOptions&)>& set,
                        bool tables_half) {
    KnobSweep ks{knob, file, default_value, {}, ""};
    if (values.empty()) return;
    if (!has_iwasaki) ks.skipped = "iwasaki is not in the GPU runtime of this build";
    else if (!tables_half && base->visibility.empty())
      ks.skipped = "no cloth object of " + c.scene_name + " is occluded: the bundle stores no visibility, so the SDF "
                   "resolution changes nothing (put an occluded scene first, e.g. --scenes pillow)";
    for (size_t i = 0; i < values.size() && ks.skipped.empty(); ++i) {
      ShadingDataBakeOptions o = bakes.paper_options();
      set(i, o);
      (tables_half ? o.bake_visibility : o.bake_tables) = false;
      std::cerr << "weft bench: sweep iwasaki " << knob << " = " << values[i] << ": baking ..." << std::flush;
      const auto t = std::chrono::steady_clock::now();
      ShadingData half = bake_shading_data(c.scene, c.fabrics, o);
      KnobRow r;
      r.value = values[i];
      r.bake_s = seconds_since(t);
      auto bundle = std::make_shared<ShadingData>();
      bundle->tables = tables_half ? std::move(half.tables) : base->tables;
      if (tables_half) bundle->visibility = base->visibility, bundle->kappa = base->kappa;
      else bundle->visibility = std::move(half.visibility), bundle->kappa = std::move(half.kappa);
      r.table_bytes = table_bytes(*bundle), r.visibility_bytes = visibility_bytes(*bundle);
      r.tables = tables_summary(*bundle);
      const CachedReference& ref = references.sg_lit(c, false);
      r.ms = render_gpu_frame(c.scene, c.fabrics, c.sgs, "iwasaki", a.speed_width, a.speed_height, 5, bundle).median_ms;
      const GpuFrame acc = render_gpu_frame(c.scene, c.fabrics, c.sgs, "iwasaki", a.width, a.height, 0, bundle);
      r.rmse = cloth_error(acc.image, ref.image, ref.kinds).relative_rmse;
      std::cerr << " " << fmt(r.bake_s) << " s; " << fmt(r.ms) << " ms/frame, relative RMSE " << fmt(r.rmse) << "\n";
      ks.rows.push_back(r);
    }
    write_knob_sweep_csv(out / file, ks);
    results.knob_sweeps.push_back(std::move(ks));
  };
  std::string paper_samples;
  for (const auto& [name, f] : c.fabrics) {
    const auto n = paper_tangent_samples(f);
    paper_samples += (paper_samples.empty() ? "" : ", ") + std::to_string(n[0]) + "+" + std::to_string(n[1]);
  }
  const ShadingDataBakeOptions paper = bakes.paper_options();
  knob_sweep("tangent samples per thread", "sweep_tangent_samples.csv", paper_samples, texts(a.sweep_tangent_samples),
             [&](size_t i, ShadingDataBakeOptions& o) { o.tangent_samples = {a.sweep_tangent_samples[i], a.sweep_tangent_samples[i]}; },
             true);
  knob_sweep("SVD error", "sweep_svd_error.csv", fmt(BakeSettings{}.svd_error), texts(a.sweep_svd_errors),
             [&](size_t i, ShadingDataBakeOptions& o) { o.svd_error = a.sweep_svd_errors[i]; }, true);
  knob_sweep("SDF resolution", "sweep_sdf_resolution.csv", std::to_string(paper.visibility.resolution),
             texts(a.sweep_sdf_resolutions),
             [&](size_t i, ShadingDataBakeOptions& o) { o.visibility.resolution = a.sweep_sdf_resolutions[i]; }, false);
  knob_sweep("SDF supersampling (rays per cell side)", "sweep_sdf_supersample.csv",
             std::to_string(paper.visibility.supersample), texts(a.sweep_sdf_supersamples),
             [&](size_t i, ShadingDataBakeOptions& o) { o.visibility.supersample = a.sweep_sdf_supersamples[i]; }, false);
}

}  // namespace weft::bench
