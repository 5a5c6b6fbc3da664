// `weft bench`: the speed/accuracy ladder of every GPU method against the reference, the
// cost-knob sweeps and the stability tables (bench/bench_run.h says what it measures and writes).
#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/commands.h"
#include "bench/bench_run.h"
#include "lighting/env_spec.h"

namespace weft {

CommandAction add_bench_command(CLI::App& app) {
  auto a = std::make_shared<bench::BenchOptions>();
  CLI::App* sub = app.add_subcommand("bench", "Speed against accuracy for every GPU method: CSV, chart, report");
  sub->add_flag("--quick", a->quick,
                "Smoke run: swatch/linen_plain at 64x48, reference SG grid 4, a fixed 8 tangent samples (no convergence), "
                "iwasaki tables grid 12 and SDF 16, 2 stress points per case; the target-error row, and "
                "sweeps of tangent samples 1,3 and SVD error 0.1,0.01 unless given");
  sub->add_option("--sweep", a->sweep,
                  "Preset: 'sky' (pillow and drape, linen and satin, procedural skies with the sun at 0-60 deg, "
                  "bigger and hazier suns, the bundled maps turned 90 deg; the weighting-table rungs (iwasaki, iwasaki_vertex, "
                  "their mask and quadrature variants; --methods narrows them) at 320x240; writes low_sun.csv/.md with the SG fit's irradiance error) or 'sky-smoke' (its smoke version: swatch, linen, 64x48, the reference at a fixed 8 tangent samples)");
  sub->add_option("--out", a->out, "Output folder (results.csv, chart.png, report.md, images/)")->capture_default_str();
  sub->add_option("--reference-cache,--cache", a->cache, "Reference cache folder (default: OUT/reference-cache)");
  sub->add_option("--scenes", a->scenes, "Scenes: preset names or .json/.gltf/.glb paths")->delimiter(',')->capture_default_str();
  sub->add_option("--fabrics", a->fabrics, "Fabrics: preset names or .json paths ('scene': each scene's own)")->delimiter(',')->capture_default_str();
  sub->add_option("--maps,--envs", a->envs, "Environment maps: names or .exr paths, NAME@DEG (rotated about +Z), "
                  "sky:elev=E,size=S,haze=T,azim=A,albedo=G (procedural; its key=value items may follow "
                  "it in this list) ('scene': each scene's own)")->delimiter(',')->capture_default_str();
  sub->add_option("--methods", a->methods, "GPU methods (default: all available)")->delimiter(',');
  sub->add_option("--speed-width", a->speed_width, "Speed: frame width")->capture_default_str();
  sub->add_option("--speed-height", a->speed_height, "Speed: frame height")->capture_default_str();
  sub->add_option("--speed-frames", a->speed_frames, "Speed: frames timed after the warm-up")->capture_default_str();
  sub->add_option("--width", a->width, "Accuracy: frame width")->capture_default_str();
  sub->add_option("--height", a->height, "Accuracy: frame height")->capture_default_str();
  sub->add_option("--sg-grid", a->sg_grid, "Reference: SG grid N (N x 2N cells per SG)")->capture_default_str();
  sub->add_option("--tangent-samples", a->tangent_samples,
                  "Reference: the minimum tangent samples per thread N_j (1..64); each reference doubles it, up to "
                  "256, until the cloth changes by at most --reference-tolerance (results.csv: reference_tangent_samples)")
      ->capture_default_str();
  sub->add_option("--reference-tolerance", a->reference_tolerance,
                  "Reference: relative RMSE between N_j and 2N_j over the cloth of every 4th pixel (x and y) that "
                  "stops the doubling (0: N_j fixed at --tangent-samples)")
      ->capture_default_str();
  sub->add_option("--sg-count", a->sg_count, "SGs fitted to each map")->capture_default_str();
  sub->add_option("--stress-points", a->stress_points, "Stability table: points per stress case")->capture_default_str();
  sub->add_flag("--no-stability", a->no_stability, "Skip the stability table");
  sub->add_flag("--no-sweeps", a->no_sweeps, "Skip the cost-knob sweeps (those --quick adds too)");
  sub->add_option("--sweep-sg-counts", a->sweep_sg_counts,
                  "SG counts to sweep on the first scene (e.g. 1,2,5,10,20,40), against its map-lit reference")
      ->delimiter(',');
  sub->add_option("--table-grid,--bake-grid", a->bake_grid,
                  "iwasaki tables: xi/omega grids NxN (0: the paper's 48; --quick uses 12)")
      ->capture_default_str();
  sub->add_option("--target-error", a->target_error,
                  "Add 'iwasaki (target E)' and 'iwasaki_vertex (target E)' rows per case, with the setting "
                  "`weft bake --target-error E` picks for each, next to their paper-default rows (0: off)")
      ->capture_default_str();
  sub->add_option("--subdivide", a->subdivide,
                  "Midpoint subdivision levels (1..3, e.g. 1,2): after each per-vertex method's row, a row "
                  "'METHOD (subdivision L)' drawn on the cloth meshes refined L levels, visibility baked on them")
      ->delimiter(',');
  sub->add_option("--sweep-tangent-samples", a->sweep_tangent_samples,
                  "iwasaki tangent samples per thread to sweep on the first scene with its own fabric and map "
                  "(e.g. 1,2,3,6), one in-memory bake each")
      ->delimiter(',');
  sub->add_option("--sweep-svd-error", a->sweep_svd_errors,
                  "iwasaki SVD error targets to sweep (they set each table's rank; e.g. 0.1,0.03,0.01,0.003)")
      ->delimiter(',');
  sub->add_option("--sweep-sdf-resolution", a->sweep_sdf_resolutions,
                  "iwasaki visibility SDF resolutions to sweep (e.g. 8,16,32,64; needs an occluded first scene)")
      ->delimiter(',');
  sub->add_option("--sweep-sdf-supersample", a->sweep_sdf_supersamples,
                  "iwasaki visibility rays per SDF cell side to sweep (e.g. 1,2,4; the paper samples 512² for 128²)")
      ->delimiter(',');
  return [a] {
    a->assets = assets_dir();
    a->envs = join_env_specs(a->envs);
    for (const auto& env : a->envs) {  // a bad spec stops the run before any bake
      try {
        if (env != "scene") parse_env_spec(env);
      } catch (const EnvSpecError& e) {
        throw UsageError(std::string("--maps: ") + e.what());
      }
    }
    try {
      return bench::run_bench(*a);
    } catch (const bench::InvalidOption& e) {
      throw UsageError(e.what());
    }
  };
}

}  // namespace weft
