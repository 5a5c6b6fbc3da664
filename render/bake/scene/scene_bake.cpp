#include "bake/scene/scene_bake.h"

#include "scene/vertex_pass_mesh.h"

#include <chrono>
#include <cstdio>

#include "bake/tables/bake_selection.h"
#include "bake/writers/bundle_fabrics.h"
#include "bake/writers/shading_data_writer.h"
#include "bake/visibility/sigmoid_gain.h"
#include "bake/visibility/visibility_mask_bake.h"
#include "bake/tables/weighting_bake.h"

namespace weft {

namespace {
double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
// The stage's progress display, or one that shows nothing.
std::function<void(double)> open_stage(const ShadingDataBakeOptions& opt, const std::string& stage) {
  if (opt.progress) return opt.progress(stage);
  return [](double) {};
}
}  // namespace

ShadingData bake_shading_data(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                               const ShadingDataBakeOptions& opt, ShadingDataBakeReport* report) {
  ShadingData out;
  ShadingDataBakeReport rep;
  auto t0 = std::chrono::steady_clock::now();
  // Per fabric, not per colour: a colourway that changes colours only reuses its fabric's tables.
  for (const std::string& fabric_name : worn_fabrics(scene)) {
    if (!opt.bake_tables) break;
    const Fabric& fabric = fabrics.at(fabric_name);
    BakeSettings settings;
    settings.tangent_samples = paper_tangent_samples(fabric);  // the paper's settings by default
    if (opt.target_error > 0) {
      auto bar = open_stage(opt, "settings " + fabric_name);
      const SelectionResult sel = select_bake_settings(fabric, opt.target_error, settings, [&](double f, std::string_view) {
        if (!opt.quiet) bar(f);
      });
      settings = sel.settings;
      if (!opt.quiet) {
        std::fprintf(stderr, "%-30s %-30s %10s %9s\n", "setting", "chosen", "error", "time");
        for (const SelectionRow& r : sel.rows)
          std::fprintf(stderr, "%-30s %-30s %10.3g %7.2f s\n", r.setting.c_str(), r.value.c_str(), r.error, r.seconds);
      }
    }
    if (opt.grid > 0) settings.xi_resolution = settings.wo_resolution = settings.wi_resolution = opt.grid;
    if (opt.tangent_samples[0] > 0 && opt.tangent_samples[1] > 0) settings.tangent_samples = opt.tangent_samples;
    if (opt.svd_error > 0) settings.svd_error = opt.svd_error;
    if (opt.lambda_levels > 0) settings.lambda_levels = opt.lambda_levels;
    settings.validate();
    auto bar = open_stage(opt, "T tables " + fabric_name);
    WeightingTables t = bake_weighting_tables(fabric, settings, [&](double f, std::string_view) {
      if (!opt.quiet) bar(f);
    });
    if (!opt.quiet) {
      bar(1.0);
      const TableSummary s = summarize(t);
      std::fprintf(stderr, "  %s: %d+%d tangent samples (%d distinct tables) x %d levels, rank %d/%.1f/%d (min/mean/max), "
                   "SVD error max %.3g, %.2f MB; rank histogram:",
                   fabric_name.c_str(), t.tangent_samples[0], t.tangent_samples[1], t.distinct_count(), t.level_count(),
                   s.min_rank, s.mean_rank, s.max_rank, s.max_error, t.bytes() / 1e6);
      for (const auto& [rank, count] : s.rank_histogram) std::fprintf(stderr, " %d:%d", rank, count);
      std::fprintf(stderr, "\n");
    }
    out.tables.emplace(fabric_name, std::move(t));
  }
  rep.tables_s = since(t0);

  t0 = std::chrono::steady_clock::now();
  for (size_t i = 0; i < scene.objects.size() && opt.bake_visibility; ++i) {
    // Every object: the cloth's for its own shading, the floor's and occluders' for their Lambertian
    // shading under the same visibility (methods/lambert_visibility.h).
    auto bar = open_stage(opt, "visibility " + scene.objects[i].name);
    SceneVisibilityStats st;
    SceneVisibilityOptions vo = opt.visibility;
    if (!scene.objects[i].is_cloth()) vo.resolution = std::min(vo.resolution, vo.lambertian_resolution);
    auto v = bake_object_visibility(scene, i, vo, [&](size_t d, size_t n) {
      if (!opt.quiet) bar(0.95 * double(d) / double(n));
    }, &st);
    if (!opt.quiet) {
      bar(1.0);
      if (v)
        std::fprintf(stderr, "  %s: %zu vertices, %d² SDF, %.1f %% of rays blocked, PCA %d terms (RMS %.4f rad, max %.3f rad), "
                     "%.2f MB, %.1f s\n",
                     scene.objects[i].name.c_str(), st.vertices, vo.resolution, 100 * st.blocked_share, v->terms,
                     v->rms_error, v->max_error,
                     4e-6 * double(v->mean.size() + v->basis.size() + v->coefficients.size()), st.seconds);
      else
        std::fprintf(stderr, "  %s: %zu vertices, no ray blocked: unoccluded, no visibility stored\n",
                     scene.objects[i].name.c_str(), st.vertices);
    }
    if (v) out.visibility.emplace(i, std::move(*v));
    // Occluded cloth also gets a bit mask (iwasaki_vertex_mask's exact V_k per vertex and SG).
    if (opt.mask_resolution > 0 && scene.objects[i].is_cloth() && out.visibility.count(i))
      if (auto m = bake_visibility_mask(scene, i, opt.mask_resolution)) {
        const VertexPassMesh& pass = pass_of(scene.objects[i].mesh);  // a subset's rows are stored at its vertices
        const size_t stored = pass.whole() ? m->vertex_count() : pass.vertices.size();
        if (!opt.quiet)
          std::fprintf(stderr, "  %s: visibility mask %d² per vertex, %.2f MB stored\n", scene.objects[i].name.c_str(),
                       opt.mask_resolution, 8e-6 * double(m->blocks()) * double(stored));
        out.masks.emplace(i, std::move(*m));
      }
  }
  rep.visibility_s = since(t0);

  if (!out.visibility.empty()) {
    t0 = std::chrono::steady_clock::now();
    auto bar = open_stage(opt, "kappa table");
    out.kappa = fit_sigmoid_gain_table(SigmoidGainTableSpec{}, [&](int d, int n) {
      if (!opt.quiet) bar(double(d) / n);
    });
    rep.kappa_s = since(t0);
    if (!opt.quiet)
      std::fprintf(stderr, "  kappa: %dx%dx%d, max |sigmoid - H| %.4f, %.1f s\n", out.kappa->spec().sigma_l_count,
                   out.kappa->spec().sigma_prime_count, out.kappa->spec().beta_count, out.kappa->max_fit_error(),
                   rep.kappa_s);
  }
  if (report) *report = rep;
  return out;
}

std::string add_baked_sections(bundle::BundleWriter& writer, const Scene& scene,
                               const std::map<std::string, std::string>& fabric_texts, const ShadingDataBakeOptions& opt,
                               ShadingData* baked) {
  ShadingDataBakeReport report;
  ShadingData data = bake_shading_data(scene, cloth_fabrics(scene, fabric_texts), opt, &report);
  add_shading_data_sections(writer, data, &scene);
  char buf[256];
  std::snprintf(buf, sizeof buf, "tables for %zu fabric(s) %.1f s, visibility for %zu object(s) %.1f s, kappa %.1f s",
                data.tables.size(), report.tables_s, data.visibility.size(), report.visibility_s, report.kappa_s);
  if (baked) *baked = std::move(data);
  return buf;
}

}  // namespace weft
