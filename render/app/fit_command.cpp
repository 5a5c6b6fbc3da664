// `weft fit`: environment map (OpenEXR equirect) → K spherical Gaussians, with the fit's error.
#include <chrono>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/asset_paths.h"
#include "lighting/env_map.h"
#include "lighting/env_spec.h"
#include "lighting/fit_error.h"
#include "lighting/preview_png.h"
#include "lighting/sg_fit.h"
#include "lighting/sg_set_io.h"
#include "journal/journal_log.h"

namespace weft {

namespace {
struct FitArgs {
  std::string map;
  int count = 10;
  bool json = false;
  std::string preview;
  std::string out;
  std::string nonfinite = "clamp";
  int grid = 128;
  int iterations = 40;
  std::string warm;
};

int run_fit(const FitArgs& a) {
  if (a.count < 1 || a.count > 64) throw UsageError("--sg-count: must be in [1, 64], got " + std::to_string(a.count));
  if (a.grid < 16 || a.grid > 1024 || a.grid % 2)
    throw UsageError("--grid: must be even and in [16, 1024], got " + std::to_string(a.grid));
  if (a.iterations < 0 || a.iterations > 1000)
    throw UsageError("--iterations: must be in [0, 1000], got " + std::to_string(a.iterations));
  if (a.nonfinite != "clamp" && a.nonfinite != "fail")
    throw UsageError("--nonfinite: expected clamp or fail, got '" + a.nonfinite + "'");
  const NonFinitePolicy policy = a.nonfinite == "clamp" ? NonFinitePolicy::clamp : NonFinitePolicy::fail;

  EnvMapRepairs repairs;
  EnvMap map;
  try {
    map = is_env_spec(a.map) ? load_env(a.map, assets_dir() / "envmaps", policy, &repairs)
                             : load_env_map(a.map, policy, &repairs);
  } catch (const EnvSpecError& e) {
    throw UsageError(e.what());
  } catch (const EnvMapError& e) {
    throw UsageError(e.what());  // a bad input file: exit code 2
  }
  if (repairs.total() > 0)
    log_line("weft fit", LogPriority::warning,
             "repaired " + std::to_string(repairs.nan) + " NaN, " + std::to_string(repairs.infinite) + " infinite and " +
                 std::to_string(repairs.negative) + " negative channel values in " + a.map + " (--nonfinite clamp)");
  if (map.width != 2 * map.height)
    log_line("weft fit", LogPriority::warning,
             "warning: " + a.map + " is " + std::to_string(map.width) + "×" + std::to_string(map.height) +
                 ", not 2:1; reading it as equirectangular anyway");

  SgLighting warm;
  if (!a.warm.empty()) {
    try {
      warm = load_sg_set(a.warm);
    } catch (const SgSetError& e) {
      throw UsageError(e.what());
    }
  }

  SgFitOptions options;
  options.count = a.count;
  options.grid_width = a.grid;
  options.max_iterations = a.iterations;
  SgFitStats stats;
  const auto start = std::chrono::steady_clock::now();
  const SgLighting sgs = fit_sgs(map, options, warm, &stats);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const SgFitError error = measure_fit_error(map, sgs);

  if (!a.out.empty()) save_sg_set(a.out, sgs);
  if (!a.preview.empty()) {
    const EnvMap fitted = render_sgs(sgs, std::min(map.width, 1024), std::min(map.width, 1024) / 2);
    const EnvMap maps[2] = {map, fitted};
    write_preview_png(a.preview, maps);
  }

  if (a.json) {
    nlohmann::ordered_json out;
    out["sgs"] = sg_set_to_json(sgs)["sgs"];
    out["error"] = {{"radiance_rmse", error.radiance_rmse},
                    {"irradiance_rmse", error.irradiance_rmse},
                    {"radiance_rmse_64x32", error.radiance_rmse_coarse}};
    out["seconds"] = seconds;
    out["map"] = {{"path", a.map}, {"width", map.width}, {"height", map.height}};
    out["repaired"] = {{"nan", repairs.nan}, {"infinite", repairs.infinite}, {"negative", repairs.negative}};
    out["iterations"] = stats.iterations;
    std::cout << out.dump() << "\n";
  } else {
    std::printf("%s: %d×%d, %d SGs fitted in %.3f s (%d LM iterations, sharpness ≤ %.0f)\n", a.map.c_str(), map.width,
                map.height, a.count, seconds, stats.iterations, stats.max_sharpness);
    std::printf("  #   axis x    axis y    axis z   sharpness    red        green      blue\n");
    for (size_t k = 0; k < sgs.size(); ++k) {
      const auto& g = sgs[k];
      std::printf("%3zu  %8.4f  %8.4f  %8.4f  %9.3f  %9.4f  %9.4f  %9.4f\n", k + 1, g.axis.x, g.axis.y, g.axis.z,
                  g.sharpness, g.amplitude.r, g.amplitude.g, g.amplitude.b);
    }
    std::printf("error (relative RMSE): radiance %.2f %% (%.2f %% at 64×32), irradiance %.2f %%\n",
                100.0 * error.radiance_rmse, 100.0 * error.radiance_rmse_coarse, 100.0 * error.irradiance_rmse);
    if (!a.preview.empty()) std::printf("preview (left: map, right: fit): %s\n", a.preview.c_str());
    if (!a.out.empty()) std::printf("saved: %s\n", a.out.c_str());
  }
  return 0;
}
}  // namespace

CommandAction add_fit_command(CLI::App& app) {
  auto a = std::make_shared<FitArgs>();
  CLI::App* sub = app.add_subcommand("fit", "Fit spherical Gaussians to an equirectangular OpenEXR environment map");
  sub->add_option("map", a->map, "Environment map (.exr, equirectangular, +Z up, Blender orientation), NAME@DEG (rotated about +Z) or sky:elev=E,azim=A,size=S,haze=T,albedo=G")->required();
  sub->add_option("--sg-count,-k,--count", a->count, "Number of SGs K")->capture_default_str();
  sub->add_flag("--json", a->json, "Print the fit and its error as one JSON object");
  sub->add_option("--preview", a->preview, "Write a PNG: the map (left) and its fit (right), tone mapped");
  sub->add_option("--out", a->out, "Save the SG set as JSON (weft-sg-set)");
  sub->add_option("--nonfinite", a->nonfinite, "NaN/Inf/negative texels: clamp (repair, counted) or fail")
      ->capture_default_str();
  sub->add_option("--grid", a->grid, "Fit grid width (the map is resampled to WIDTH×WIDTH/2)")->capture_default_str();
  sub->add_option("--iterations", a->iterations, "Levenberg–Marquardt iterations at most")->capture_default_str();
  sub->add_option("--warm", a->warm, "Start from this SG set (JSON), e.g. the previous frame's fit");
  return [a] { return run_fit(*a); };
}

}  // namespace weft
