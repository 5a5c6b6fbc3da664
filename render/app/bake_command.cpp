// `weft bake`: writes a kiosk bundle (BUNDLE_FORMAT.md): the scene sections (meshes, materials,
// fabric parameters, camera, default SGs) and the weighting tables (T per cloth fabric, per-vertex
// visibility PCA for occluded cloth, κ).
#include <chrono>
#include <cstdio>

#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/option_spelling.h"
#include "app/progress_bar.h"
#include "bake/writers/bundle_fabrics.h"
#include "bake/scene/scene_bake.h"
#include "bake/writers/scene_bundle_writer.h"
#include "bake/selection/selection_bundle.h"
#include "bundle/bundle_writer.h"
#include "lighting/env_map.h"
#include "lighting/sg_fit.h"
#include "lighting/sg_set_io.h"
#include "runtime/visibility_mask.h"
#include "scene/mesh_subdivision.h"
#include "scene/mesh_vertex_order.h"
#include "scene/scene_file.h"
#include "scene/vertex_pass_mesh.h"

namespace weft {
namespace {

struct BakeArgs {
  std::string scene, fabric, sgs_file, out;
  int fit_sgs = 0;
  bool only_scene_fabrics = false, no_tables = false, no_masks = false, choose_rung = false;
  int sdf_resolution = 128;  // the paper's
  // The default bake's economies, measured harmless (render/bake/README.md, "The default bake"):
  int lambertian_sdf_resolution = 32, lambda_levels = 5;
  std::vector<int> samples;
  int subdivide = -1;  // ≥ 0: midpoint subdivision levels of the cloth meshes (the search's choice when < 0)
  SceneSelectionOptions select;  // --target-error > 0: the scene-level search (bake/selection/scene_selection.h); holds --table-grid
};

void progress(int step, int steps, const std::string& what) { std::fprintf(stderr, "bake [%d/%d] %s\n", step, steps, what.c_str()); }

int run_bake(const BakeArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  constexpr int kSteps = 5;
  if (a.sdf_resolution % 2 || a.lambertian_sdf_resolution % 2)
    throw UsageError(std::string(a.sdf_resolution % 2 ? "--sdf-resolution" : "--floor-sdf-resolution") + ": must be even");
  SceneBundleInput in;
  progress(1, kSteps, "scene '" + a.scene + "'");
  in.scene = as_usage("--scene", [&] { return load_scene_named(a.scene, assets_dir(), a.fabric); });
  for (const std::string& w : in.scene.warnings) std::cerr << "weft bake: warning: " << w << "\n";
  if (!a.fabric.empty())
    for (auto& o : in.scene.cloth_objects()) o.fabric = a.fabric;
  const bool search = !a.no_tables && a.select.target_error > 0;  // it chooses the SGs: scene sections after it
  // Spatial vertex order before anything per vertex is baked; the search orders its densities itself.
  in.scene = order_scene_meshes(std::move(in.scene));
  if (a.subdivide > 0 && !search) in.scene = refine_and_order_meshes(std::move(in.scene), a.subdivide);
  if (!search) std::fputs(set_pass_meshes(in.scene, "  ").c_str(), stderr);  // the search's: after it refines
  progress(2, kSteps, "fabrics");
  try {
    in.fabrics = bundle_fabric_texts(in.scene, assets_dir() / "fabrics", a.only_scene_fabrics);
  } catch (const BundleFabricError& e) {
    throw UsageError(e.what());
  }
  std::string lighting, tables_line = "no weighting tables (--no-tables)";
  if (!a.sgs_file.empty()) {
    progress(3, kSteps, "SGs from " + a.sgs_file);
    in.sgs = as_usage("--sgs", [&] { return load_sg_set(a.sgs_file); });
    lighting = a.sgs_file;
  } else {
    const auto map_file = env_map_file(in.scene.environment, assets_dir() / "envmaps");
    progress(3, kSteps, "fitting " + std::to_string(a.fit_sgs > 0 ? a.fit_sgs : 10) + " SGs to " + map_file.string());
    SgFitOptions opt;
    opt.count = a.fit_sgs > 0 ? a.fit_sgs : 10;  // the product card's 10 SGs by default
    in.sgs = fit_sgs(load_env_map(map_file, NonFinitePolicy::clamp), opt);  // as `weft fit` does by default
    lighting = "fitted to " + in.scene.environment;
  }
  if (in.sgs.empty()) throw UsageError("no SG lighting: the fit gave none; give --sgs FILE");
  bundle::BundleWriter writer;
  if (!search) add_scene_sections(writer, in);
  if (!a.no_tables) {
    progress(4, kSteps, "weighting tables (T, visibility, kappa)");
    ShadingDataBakeOptions opt;
    opt.progress = open_progress_bar, opt.mask_resolution = a.no_masks ? 0 : kMaskResolution;
    opt.visibility.resolution = a.sdf_resolution, opt.visibility.lambertian_resolution = a.lambertian_sdf_resolution;
    opt.grid = a.select.grid, opt.lambda_levels = a.lambda_levels;
    if (!a.samples.empty()) opt.tangent_samples = {a.samples[0], a.samples[1]};  // two, in [1, 64]: CLI's checks
    // Fitted by default: the search chooses their count too.
    const auto sg_map = a.sgs_file.empty() && a.fit_sgs == 0 ? env_map_file(in.scene.environment, assets_dir() / "envmaps")
                                                             : std::filesystem::path();
    SceneSelectionOptions select = a.select;
    select.visibility.lambertian_resolution = a.lambertian_sdf_resolution;
    select.views.progress = open_progress_bar;
    ShadingData baked;
    try {
      tables_line = search ? add_selected_bundle(writer, in, select, sg_map)
                           : add_baked_sections(writer, in.scene, in.fabrics, opt, a.choose_rung ? &baked : nullptr);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    if (a.choose_rung) tables_line += "; " + add_rung_choice(writer, in, std::move(baked), select.views, select.cache);
  }
  progress(5, kSteps, "writing " + a.out);
  const auto bytes = writer.to_bytes();
  try {
    writer.write_file(a.out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  size_t triangles = 0;
  for (const auto& o : in.scene.objects) triangles += o.mesh.triangles.size();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fprintf(stderr, "baked %s: scene '%s', %zu objects, %zu triangles, %zu fabrics, %zu SGs (%s); %zu sections, %zu bytes, "
               "%.2f s\n  %s; bundle %.2f MB\n",
               a.out.c_str(), in.scene.name.c_str(), in.scene.objects.size(), triangles, in.fabrics.size(), in.sgs.size(),
               lighting.c_str(), writer.section_count(), bytes.size(), s, tables_line.c_str(), bytes.size() / 1e6);
  return 0;
}

}  // namespace

CommandAction add_bake_command(CLI::App& app) {
  auto a = std::make_shared<BakeArgs>();
  CLI::App* sub = app.add_subcommand("bake", "Bake a scene into a kiosk bundle (meshes, fabrics, camera, default SGs, weighting tables)");
  sub->add_option("--scene", a->scene, "Scene: a preset (assets/scenes/NAME.json) or a path to a .json scene or a .gltf/.glb file")->required();
  sub->add_option("--fabric", a->fabric, "Fabric (preset name or .json file) for every cloth object (default: each object's own; a glTF naming no cloth: every material)");
  sub->add_option("--sgs", a->sgs_file, "Default SG lighting from a weft-sg-set file (weft fit --out)");
  sub->add_option("--sg-count,--fit-sgs", a->fit_sgs, "SGs fitted to the scene's environment map when no --sgs is given (default 10)")->check(CLI::Range(1, 64));
  sub->add_flag("--only-scene-fabrics", a->only_scene_fabrics, "Store only the cloth objects' fabrics (no other presets for the fabric knob)");
  sub->add_option("--out", a->out, "Bundle file to write")->required();
  auto* no_tables = sub->add_flag("--no-tables", a->no_tables, "Scene sections only (no weighting tables: enough for sgpoint)");
  auto* target = sub->add_option("--target-error", a->select.target_error, "Choose every cost knob (SG count unless --sgs/--sg-count, samples, levels, SVD, SDF, PCA, cloth mesh "
                  "subdivision unless --subdivide, per-vertex or per-pixel) for this image error on the scene's views at the least frame time, then bytes (0: the paper's)")->check(CLI::Range(0.0, 0.5));
  auto* no_masks = sub->add_flag("--no-masks", a->no_masks, "No per-vertex visibility masks: a smaller bundle (512 B less per occluded cloth vertex) without the rungs that read them (iwasaki_mask, iwasaki_vertex_mask, the *_quadrature rungs), so --method auto falls back to iwasaki_vertex on occluded cloth. The --target-error search bakes none")->excludes(no_tables)->excludes(target);
  sub->add_flag("--choose-rung", a->choose_rung, "Measure the kiosk's per-vertex rung with the SDF's visibility and with the masks' (iwasaki_vertex_quadrature, iwasaki_vertex_mask_quadrature) on the scene's views against a reference (rendered once, cached: minutes) and record the closer for --method auto")->excludes(no_tables)->excludes(target)->excludes(no_masks);
  sub->add_option("--choose-width", a->select.views.width, "Width of --choose-rung's (and --target-error's) views (their references cost minutes)")->check(CLI::Range(8, 1024))->capture_default_str();
  sub->add_option("--choose-height", a->select.views.height, "Height of those views")->check(CLI::Range(8, 1024))->capture_default_str();
  old_spelling(sub->add_option_function<std::vector<int>>("--choose-size", [a](const std::vector<int>& wh) { a->select.views.width = wh[0], a->select.views.height = wh[1]; })->expected(2)->check(CLI::Range(8, 1024)));
  sub->add_option("--reference-cache", a->select.cache, "Folder of --target-error's cached reference renders (default: $XDG_CACHE_HOME/weft/bake-references)");
  sub->add_option("--sdf-resolution", a->sdf_resolution, "Visibility SDF grid per vertex, N x N (even)")->check(CLI::Range(8, 256))->capture_default_str();
  sub->add_option("--floor-sdf-resolution", a->lambertian_sdf_resolution, "The same for floors and occluders (Lambertian; at most --sdf-resolution)")->check(CLI::Range(8, 256))->capture_default_str();
  sub->add_option("--table-grid,--grid", a->select.grid, "Direction grids of the T tables, N x N (default: the paper's 48; smaller bakes faster)")->check(CLI::Range(4, 128));
  sub->add_option("--lambda-levels", a->lambda_levels, "Sharpness levels of the T tables, log-spaced over λ 1/16..1024 (the paper: 9 over 4..1024; 15 puts them ×2 apart)")->check(CLI::Range(2, 33))->capture_default_str();
  sub->add_option("--tangent-samples,--samples", a->samples, "Tangent samples per thread N1 N2 (default: the paper's)")->expected(2)->check(CLI::Range(1, 64));
  sub->add_option_function<int>("--subdivide", [a](const int& n) { a->subdivide = n, a->select.knobs.subdivisions = {n}; }, "Midpoint subdivision levels of the cloth meshes (each x4 triangles: finer per-vertex shading, more vertices to shade and store; default 0, or with --target-error the search's choice)")->check(CLI::Range(0, kMaxSubdivision));
  return [a] { return run_bake(*a); };
}

}  // namespace weft
