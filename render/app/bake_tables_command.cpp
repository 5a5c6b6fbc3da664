// `weft bake-tables`: bakes only the weighting tables T_{t,λ} of one fabric
// and prints what was chosen and measured. `weft bake` writes them into the scene bundle;
// this command exists to measure the table bake on its own.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/stage_progress_bar.h"
#include "bake/tables/azimuthal_bake.h"
#include "bake/tables/bake_selection.h"
#include "bake/tables/weighting_bake.h"

namespace weft {

namespace {
std::string format_bytes(std::size_t b) {
  char buf[32];
  if (b >= (1u << 20)) std::snprintf(buf, sizeof buf, "%.2f MiB", b / 1048576.0);
  else std::snprintf(buf, sizeof buf, "%.1f KiB", b / 1024.0);
  return buf;
}
std::string format_number(double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

struct BakeTablesArgs {
  std::string fabric = "linen_plain";
  double target_error = 0.0;  // 0: paper defaults
  std::vector<int> samples;
  int levels = 0;
  double svd_error = 0.0;
  int wi_resolution = 0;
};

int run_bake_tables(const BakeTablesArgs& a) {
  if (a.target_error < 0.0 || a.target_error >= 1.0 || !std::isfinite(a.target_error))
    throw UsageError("--target-error: must be in (0, 1), got " + std::to_string(a.target_error));
  const Fabric fabric = load_fabric_named(a.fabric, assets_dir() / "fabrics");
  BakeSettings settings;
  settings.tangent_samples = paper_tangent_samples(fabric);
  std::vector<SelectionRow> rows;
  StageProgressBar bar;
  const auto start = std::chrono::steady_clock::now();
  if (a.target_error > 0.0) {
    std::cerr << "weft bake-tables: choosing settings for target error " << a.target_error << "\n";
    SelectionResult sel = select_bake_settings(fabric, a.target_error, settings, [&](double f, std::string_view s) {
      bar(f, s);
    });
    settings = sel.settings;
    rows = sel.rows;
  }
  if (!a.samples.empty()) {
    if (a.samples.size() != 2) throw UsageError("--tangent-samples: give two counts N1,N2");
    settings.tangent_samples = {a.samples[0], a.samples[1]};
  }
  if (a.levels > 0) settings.lambda_levels = a.levels;
  if (a.svd_error > 0.0) settings.svd_error = a.svd_error;
  if (a.wi_resolution > 0) settings.wi_resolution = a.wi_resolution;
  try {
    settings.validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }

  std::cerr << "weft bake-tables: " << fabric.name << ": " << settings.tangent_samples[0] << "+"
            << settings.tangent_samples[1] << " tangent samples, " << settings.lambda_levels << " sharpness levels λ "
            << settings.lambda_min << ".." << settings.lambda_max << ", ξ " << settings.xi_resolution << "², ω_o "
            << settings.wo_resolution << "², W on " << settings.wi_resolution << "² ω_i nodes, SVD error ≤ "
            << settings.svd_error << "\n";
  BakeTimings timings;
  const auto bake_start = std::chrono::steady_clock::now();
  const WeightingTables tables =
      bake_weighting_tables(fabric, settings, [&](double f, std::string_view s) { bar(f, s); }, &timings);
  const double bake_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - bake_start).count();
  const auto az_start = std::chrono::steady_clock::now();
  bar(0.0, "azimuthal table T_m");
  const AzimuthalTable azimuthal = bake_azimuthal_table();
  bar(1.0, "azimuthal table T_m");
  const double az_error = azimuthal_interpolation_error(azimuthal);
  const double az_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - az_start).count();
  const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const TableSummary summary = summarize(tables);
  rows.push_back({"SVD rank per (t, λ)",
                  std::to_string(summary.min_rank) + "/" + format_number(summary.mean_rank, 3) + "/" +
                      std::to_string(summary.max_rank) + " (min/mean/max)",
                  summary.max_error, tables.bytes(), timings.compress_s});
  const AzimuthalTableSettings& az = azimuthal.settings;
  rows.push_back({"azimuthal table T_m (m 0..10)",
                  std::to_string(az.phi_o_nodes) + "x" + std::to_string(az.phi_k_nodes) + "x" +
                      std::to_string(az.lambda_nodes) + " (φ_o×φ_k×λ')",
                  az_error, azimuthal.bytes(), az_s});

  std::printf("\nsetting                        chosen                          error      bytes        time\n");
  for (const SelectionRow& r : rows)
    std::printf("%-30s %-30s %10.3g %10s %9.2f s\n", r.setting.c_str(), r.value.c_str(), r.error,
                r.bytes ? format_bytes(r.bytes).c_str() : "-", r.seconds);
  std::printf("bake: %.2f s (W grid %.2f s, G·W %.2f s, SVD %.2f s); with selection %.2f s\n", bake_s,
              timings.weights_s, timings.convolve_s, timings.compress_s, total_s);
  std::printf("tables: %d samples (%d distinct) × %d levels, %s, relative Frobenius error mean %.3g max %.3g\n",
              tables.sample_count(), tables.distinct_count(), tables.level_count(), format_bytes(tables.bytes()).c_str(), summary.mean_error,
              summary.max_error);
  std::printf("rank histogram:");
  for (const auto& [rank, count] : summary.rank_histogram) std::printf(" %d:%d", rank, count);
  std::printf("\nranks by level (λ: rank per sample):\n");
  for (int l = 0; l < tables.level_count(); ++l) {
    std::printf("  λ %7.1f:", tables.lambdas[l]);
    for (int t = 0; t < tables.sample_count(); ++t) std::printf(" %3d", tables.table(t, l).rank);
    std::printf("\n");
  }
  return 0;
}
}  // namespace

CommandAction add_bake_tables_command(CLI::App& app) {
  auto a = std::make_shared<BakeTablesArgs>();
  CLI::App* sub = app.add_subcommand(
      "bake-tables", "Bake only the SG-convolved weighting tables T of one fabric and report time, size, ranks, error");
  sub->add_option("--fabric", a->fabric, "Fabric: a preset name (assets/fabrics/NAME.json) or a .json file")->capture_default_str();
  sub->add_option("--target-error", a->target_error,
                  "Choose tangent samples, λ levels and SVD ranks so each table's relative error stays under E "
                  "(default: the paper's settings)");
  sub->add_option("--tangent-samples,--samples", a->samples, "Override tangent samples per thread: N1,N2")->delimiter(',');
  sub->add_option("--lambda-levels,--levels", a->levels, "Override the number of λ levels (4..1024, log-spaced)")
      ->check(CLI::Range(1, 64));
  sub->add_option("--svd-error", a->svd_error, "Override the relative SVD truncation error per table")
      ->check(CLI::Range(1e-6, 0.999));
  sub->add_option("--wi-resolution", a->wi_resolution, "Override the ω_i node grid W is sampled on (n×n)")
      ->check(CLI::Range(2, 1024));
  return [a] { return run_bake_tables(*a); };
}

}  // namespace weft
