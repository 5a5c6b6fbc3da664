// `weft bench`: the speed/accuracy ladder (issue 6). Every GPU method × scene × fabric ×
// environment: speed at 640×480 (median over ≥ 20 frames after a warm-up, glFinish
// included) and accuracy at 320×240 as relative RMSE over the cloth pixels against a cached
// `reference` render under the same SGs; the `weft bake --target-error` point of iwasaki next
// to its paper-default row; sweeps of iwasaki's cost knobs (SG count, tangent samples, SVD
// error, SDF resolution) on the first scene; then the stability table (render/bench/stability.h)
// and, from the teapot images, the thin-occluder table (errors inside the sun's shadow).
// Writes results.csv, sweep_*.csv, chart.png, report.md and the images the report shows into --out.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/gpu_render.h"
#include "app/iwasaki_bake.h"
#include "bake/bake_selection.h"
#include "runtime/weighting_tables.h"
#include "bench/chart.h"
#include "bench/image_metrics.h"
#include "bench/reference_cache.h"
#include "bench/shadow_mask.h"
#include "bench/stability.h"
#include "core/fabric.h"
#include "gpu/scene_renderer.h"
#include "lighting/env_map.h"
#include "lighting/sg_fit.h"
#include "reference/environment_samples.h"
#include "reference/scene_render.h"
#include "scene/scene.h"

namespace weft {

namespace {

// The ladder of DESIGN.md §4, data-driven: a method is benchmarked when the GPU runtime has
// it (gpu::method_names()); the rest are reported as missing. `scenes` limits a method to the
// scenes it is for; `thin_reference`: measured against the reference with cloth as seed 004's
// thin layer (ReferenceRenderOptions::thin_cloth) instead of opaque cloth.
struct LadderEntry {
  std::string name;
  std::set<std::string> scenes;  // empty: every scene
  bool thin_reference = false;
};
const std::vector<LadderEntry>& ladder() {
  static const std::vector<LadderEntry> l = {
      {"iwasaki", {}, false},
      {"iwasaki_vertex", {}, false},
      {"mizutani", {}, false},
      {"sgpoint", {}, false},
      {"mdfrot", {}, false},
      {"sheen", {}, false},
      {"thin", {"curtain"}, true},
  };
  return l;
}

// The thin-occluder stress case (issue 6): the scene whose spout and handle shadow the cloth
// under a sharp sun. Its rows also get errors inside and beside the sun's shadow.
const std::string kThinOccluderScene = "teapot";

struct BenchArgs {
  bool quick = false;
  std::string out = "bench-out";
  std::string cache;  // default: <out>/reference-cache
  std::vector<std::string> scenes{"swatch", "pillow", "drape", "teapot", "curtain"};
  std::vector<std::string> fabrics{"scene"};
  std::vector<std::string> envs{"scene"};
  std::vector<std::string> methods;  // empty: all available
  int speed_width = 640, speed_height = 480, speed_frames = 20;
  int width = 320, height = 240;
  int sg_grid = 8, tangent_samples = 16, sg_count = 10;
  int stress_points = 24;
  bool no_stability = false;
  int bake_grid = 0;           // iwasaki tables' ξ/ω grids n×n; 0: the paper's 48 (12 with --quick)
  double target_error = 0.05;  // > 0: an `iwasaki (target E)` row baked by bake_selection.h
  // Cost-knob sweep: SG counts fitted to the first scene's own map, accuracy against the
  // reference lit by the map itself (so the fit's error counts), speed over 5 frames.
  std::vector<int> sweep_sg_counts;
  // iwasaki's bake knobs, one at a time from the paper-default bundle, on the first scene with
  // its own fabric and map, against the main rows' reference (same SGs).
  std::vector<int> sweep_tangent_samples;  // per thread
  std::vector<double> sweep_svd_errors;
  std::vector<int> sweep_sdf_resolutions;
  std::vector<int> sweep_sdf_supersamples;  // visibility rays per SDF cell side (the paper: 512² → 128², 4)
};

struct SweepRow {
  std::string method;
  int sg_count = 0;
  double ms = 0.0, rmse = 0.0;
};

// One point of a bake-knob sweep.
struct KnobRow {
  std::string value;
  double ms = 0.0, rmse = 0.0, bake_s = 0.0;
  size_t table_bytes = 0, visibility_bytes = 0;
  std::string tables;  // what the tables hold (tables_summary)
};
struct KnobSweep {
  std::string knob, file, default_value;
  std::vector<KnobRow> rows;
  std::string skipped;  // why nothing was measured
};

struct Row {
  std::string scene, fabric, env, method;
  double ms = 0.0;
  int frames = 0;
  double rmse = -1.0;  // < 0: not measured
  size_t cloth_pixels = 0;
  size_t bundle_bytes = 0;  // iwasaki rows: weighting tables + visibility PCA in the bundle
  std::string tables;       // iwasaki rows: what the tables hold
  std::string note, image, error_image, reference_image;
  // Thin-occluder scene only (< 0: not measured): bench::masked_error in the sun's shadow and
  // in the sunlit band beside it.
  double shadow_rmse = -1.0, shadow_ratio = -1.0, band_ratio = -1.0;
  size_t shadow_pixels = 0, band_pixels = 0;
  bool visibility = false;  // the method shades with scene visibility (seed 000's SDF)
  // Floor and occluders (Lambertian pixels, < 0: none in view): bench::masked_error there.
  double lambert_rmse = -1.0, lambert_ratio = -1.0;
};

std::string fmt(double x, int digits = 3) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, x);
  return b;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

template <class T>
std::string joined_numbers(const std::vector<T>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + fmt(double(x), 4);
  return s;
}

size_t table_bytes(const IwasakiBundleData& d) {
  size_t b = 0;
  for (const auto& [name, t] : d.tables) b += t.bytes();
  return b;
}
size_t visibility_bytes(const IwasakiBundleData& d) {
  size_t b = 0;
  for (const auto& [i, v] : d.visibility) b += sizeof(float) * (v.mean.size() + v.basis.size() + v.coefficients.size());
  return b;
}
// "linen_plain: 3+3 samples, 9 levels, rank 7.1 (mean), 0.42 MB" per fabric.
std::string tables_summary(const IwasakiBundleData& d) {
  std::string s;
  for (const auto& [name, t] : d.tables) {
    const TableSummary m = summarize(t);
    s += (s.empty() ? "" : "; ") + name + ": " + std::to_string(t.tangent_samples[0]) + "+" +
         std::to_string(t.tangent_samples[1]) + " samples, " + std::to_string(t.level_count()) + " levels, rank " +
         fmt(m.mean_rank, 3) + " (mean), " + fmt(t.bytes() / 1e6, 3) + " MB";
  }
  return s;
}

// The command that regenerates this run, every setting spelled out.
std::string command_line(const BenchArgs& a, bool quick) {
  std::ostringstream c;
  c << "weft bench";
  if (quick) c << " --quick";
  else
    c << " --scenes " << joined(a.scenes) << " --fabrics " << joined(a.fabrics) << " --envs " << joined(a.envs)
      << " --speed-width " << a.speed_width << " --speed-height " << a.speed_height << " --width " << a.width
      << " --height " << a.height << " --sg-grid " << a.sg_grid << " --tangent-samples " << a.tangent_samples
      << " --stress-points " << a.stress_points;
  c << " --speed-frames " << a.speed_frames << " --sg-count " << a.sg_count;
  if (!a.methods.empty()) c << " --methods " << joined(a.methods);
  if (a.no_stability) c << " --no-stability";
  if (!quick && a.bake_grid > 0) c << " --bake-grid " << a.bake_grid;
  c << " --target-error " << fmt(a.target_error, 4);
  if (!a.sweep_sg_counts.empty()) c << " --sweep-sg-counts " << joined_numbers(a.sweep_sg_counts);
  if (!a.sweep_tangent_samples.empty()) c << " --sweep-tangent-samples " << joined_numbers(a.sweep_tangent_samples);
  if (!a.sweep_svd_errors.empty()) c << " --sweep-svd-error " << joined_numbers(a.sweep_svd_errors);
  if (!a.sweep_sdf_resolutions.empty()) c << " --sweep-sdf-resolution " << joined_numbers(a.sweep_sdf_resolutions);
  if (!a.sweep_sdf_supersamples.empty()) c << " --sweep-sdf-supersample " << joined_numbers(a.sweep_sdf_supersamples);
  c << " --out " << a.out;
  return c.str();
}

void write_image_png(const Image& img, const std::filesystem::path& file, double exposure) { write_png(img, file, exposure); }

int run_bench(BenchArgs a) {
  if (a.quick) {
    a.scenes = {"swatch"};
    a.fabrics = {"linen_plain"};
    a.envs = {"scene"};
    a.speed_width = 64, a.speed_height = 48;  // --speed-frames stays (20 by default)
    a.width = 64, a.height = 48;
    a.sg_grid = 4, a.tangent_samples = 8;
    a.stress_points = 2;
    a.bake_grid = 12;
    // Smoke versions of iwasaki's knob sweeps (grid-12 tables: seconds each). No SDF sweep:
    // swatch has no occluded cloth.
    if (a.sweep_tangent_samples.empty()) a.sweep_tangent_samples = {1, 3};
    if (a.sweep_svd_errors.empty()) a.sweep_svd_errors = {0.1, 0.01};
  }
  if (a.speed_frames < 1 || a.speed_frames > 1000) throw UsageError("--speed-frames: must be within 1..1000");
  if (a.width < 8 || a.height < 8 || a.width > 4096 || a.height > 4096 || a.speed_width < 8 || a.speed_height < 8 ||
      a.speed_width > 4096 || a.speed_height > 4096)
    throw UsageError("--width/--height/--speed-width/--speed-height: must be within 8..4096");
  if (a.sg_grid < 1 || a.sg_grid > 256) throw UsageError("--sg-grid: must be within 1..256");
  if (a.tangent_samples < 1 || a.tangent_samples > 64) throw UsageError("--tangent-samples: must be within 1..64");
  if (a.sg_count < 1 || a.sg_count > 40) throw UsageError("--sg-count: must be within 1..40");
  if (a.stress_points < 0 || a.stress_points > 1000) throw UsageError("--stress-points: must be within 0..1000");
  if (a.bake_grid != 0 && (a.bake_grid < 4 || a.bake_grid > 96)) throw UsageError("--bake-grid: must be 0 or within 4..96");
  if (!(a.target_error >= 0.0 && a.target_error < 1.0)) throw UsageError("--target-error: must be within [0, 1)");
  for (int k : a.sweep_sg_counts)
    if (k < 1 || k > 40) throw UsageError("--sweep-sg-counts: each must be within 1..40");
  for (int k : a.sweep_tangent_samples)
    if (k < 1 || k > 32) throw UsageError("--sweep-tangent-samples: each must be within 1..32");
  for (double e : a.sweep_svd_errors)
    if (!(e > 0.0 && e < 1.0)) throw UsageError("--sweep-svd-error: each must be within (0, 1)");
  for (int r : a.sweep_sdf_resolutions)
    if (r < 4 || r > 128) throw UsageError("--sweep-sdf-resolution: each must be within 4..128");
  for (int r : a.sweep_sdf_supersamples)
    if (r < 1 || r > 4) throw UsageError("--sweep-sdf-supersample: each must be within 1..4");

  // iwasaki draws from seed 000 tables: baked in memory, once per scene, fabric set and
  // setting (small grids with --quick; the paper's 48 otherwise, minutes each on two cores).
  std::map<std::string, std::shared_ptr<const IwasakiBundleData>> iwasaki_bakes;
  auto paper_bake = [&] {
    IwasakiBakeOptions o;
    o.quiet = true;
    o.grid = a.bake_grid;
    if (a.quick) o.visibility.resolution = 16;
    return o;
  };
  auto bake_key = [](const Scene& scene, const std::map<std::string, Fabric>& fabrics) {
    std::string key = scene.name;
    for (const auto& [name, f] : fabrics) key += "/" + name;
    return key;
  };
  auto bake = [&](const std::string& key, const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                  const IwasakiBakeOptions& o) -> std::shared_ptr<const IwasakiBundleData> {
    auto& data = iwasaki_bakes[key];
    if (!data) {
      std::cerr << "weft bench: baking seed 000 tables for " << key << " ..." << std::flush;
      const auto t = std::chrono::steady_clock::now();
      data = std::make_shared<IwasakiBundleData>(bake_iwasaki(scene, fabrics, o));
      std::cerr << " " << fmt(seconds_since(t)) << " s\n";
    }
    return data;
  };
  // Every iwasaki variant of the runtime (e.g. iwasaki_vertex) reads the same bundle, and
  // mizutani takes its W tables from it (baked for the paper's tangent samples).
  auto tables_for = [&](const std::string& method, const Scene& scene,
                        const std::map<std::string, Fabric>& fabrics) -> std::shared_ptr<const IwasakiBundleData> {
    if (!gpu::reads_seed000_tables(method)) return nullptr;
    return bake(bake_key(scene, fabrics), scene, fabrics, paper_bake());
  };
  const auto available = gpu::method_names();
  const bool has_iwasaki = std::find(available.begin(), available.end(), "iwasaki") != available.end();
  std::vector<LadderEntry> run;
  std::vector<std::string> missing;
  for (const auto& m : a.methods) {
    bool ok = false;
    for (const auto& n : available) ok = ok || n == m;
    if (!ok) throw UsageError("--methods: '" + m + "' is not a GPU method here");
  }
  for (const auto& e : ladder()) {
    const bool has = std::find(available.begin(), available.end(), e.name) != available.end();
    if (!has) {
      missing.push_back(e.name);
      continue;
    }
    if (a.methods.empty() || std::find(a.methods.begin(), a.methods.end(), e.name) != a.methods.end()) run.push_back(e);
  }
  for (const auto& n : available) {  // a GPU method the ladder does not list still runs
    bool listed = false;
    for (const auto& e : ladder()) listed = listed || e.name == n;
    if (!listed && (a.methods.empty() || std::find(a.methods.begin(), a.methods.end(), n) != a.methods.end()))
      run.push_back({n, {}, false});
  }
  const bool run_iwasaki = std::any_of(run.begin(), run.end(), [](const LadderEntry& e) { return e.name == "iwasaki"; });
  const std::string target_label = "iwasaki (target " + fmt(a.target_error) + ")";

  const std::filesystem::path out(a.out);
  const std::filesystem::path cache = a.cache.empty() ? out / "reference-cache" : std::filesystem::path(a.cache);
  std::filesystem::create_directories(out / "images");
  const auto t_start = std::chrono::steady_clock::now();
  const auto assets = assets_dir();
  std::vector<Row> rows;
  std::string thin_occluder_case;  // what the thin-occluder table's text says of its case
  std::set<std::string> written;  // reference PNGs written this run
  std::string renderer;
  double reference_seconds = 0.0;
  int references_rendered = 0, references_cached = 0;

  // One benchmark case: a scene with its fabrics (preset → fabric) and map, the fitted SGs.
  struct Case {
    std::string scene_name, fabric_label, env, tag;
    Scene scene;
    std::map<std::string, Fabric> fabrics;
    SgLighting sgs;
    std::shared_ptr<const bench::ShadowMask> shadow;  // the thin-occluder scene, at the accuracy size
  };
  auto make_case = [&](const std::string& scene_name, const std::string& fabric_arg, const std::string& env_arg) {
    Case c;
    c.scene_name = scene_name;
    try {
      c.scene = load_scene_preset(scene_name, assets / "scenes");
    } catch (const SceneError& e) {
      throw UsageError(e.what());
    }
    for (auto& o : c.scene.objects)
      if (o.material == Material::cloth) {
        if (fabric_arg != "scene") o.fabric = fabric_arg;
        if (!c.fabrics.count(o.fabric)) c.fabrics.emplace(o.fabric, load_fabric_preset(o.fabric, assets / "fabrics"));
      }
    c.fabric_label = fabric_arg == "scene" ? c.fabrics.begin()->first : fabric_arg;
    c.env = env_arg == "scene" ? c.scene.environment : env_arg;
    const auto env_file = assets / "envmaps" / (c.env + ".exr");
    if (!std::filesystem::exists(env_file)) throw UsageError("--envs: no environment map " + env_file.string());
    const EnvMap map = load_env_map(env_file, NonFinitePolicy::clamp, nullptr);
    SgFitOptions fit;
    fit.count = a.sg_count;
    c.sgs = fit_sgs(map, fit);
    c.tag = scene_name + "_" + c.fabric_label + "_" + c.env;
    if (scene_name == kThinOccluderScene)
      c.shadow = std::make_shared<bench::ShadowMask>(bench::sun_shadow_mask(c.scene, c.sgs, a.width, a.height));
    return c;
  };

  // The references (opaque cloth, and thin cloth for see-through methods), from the cache
  // when every input is the same.
  std::map<std::string, bench::CachedReference> references;
  auto reference = [&](const Case& c, bool thin) -> const bench::CachedReference& {
    const std::string name = c.tag + (thin ? "_thin" : "");
    if (references.count(name)) return references.at(name);
    bench::InputHash h;
    h.add(bench::kReferenceCodeVersion).add_file(assets / "scenes" / (c.scene_name + ".json"));
    for (const auto& entry : std::filesystem::directory_iterator(assets / "scenes"))
      if (entry.path().extension() == ".bpt") h.add_file(entry.path());  // mesh data scenes read
    for (const auto& [name, f] : c.fabrics) h.add(name).add_file(assets / "fabrics" / (name + ".json"));
    h.add(c.env).add(thin ? "thin" : "opaque");
    for (const auto& g : c.sgs) {
      h.add_number(g.axis.x).add_number(g.axis.y).add_number(g.axis.z).add_number(g.sharpness);
      h.add_number(g.amplitude.r).add_number(g.amplitude.g).add_number(g.amplitude.b);
    }
    h.add_number(a.width).add_number(a.height).add_number(a.sg_grid).add_number(a.tangent_samples);
    const auto cache_file = cache / (name + "_" + h.hex() + ".ref");
    auto ref = bench::load_reference(cache_file);
    if (ref) {
      ++references_cached;
    } else {
      std::cerr << "weft bench: reference " << name << " at " << a.width << "x" << a.height << " ..." << std::flush;
      ReferenceLighting lighting;
      lighting.sgs = c.sgs;
      lighting.background = [sgs = c.sgs](const glm::dvec3& d) { return evaluate(sgs, d); };
      ReferenceRenderOptions opt;
      opt.width = a.width, opt.height = a.height, opt.sg_grid = a.sg_grid, opt.tangent_samples = a.tangent_samples;
      opt.check_convergence = false;
      opt.thin_cloth = thin;
      const auto t = std::chrono::steady_clock::now();
      const ReferenceRenderer rr(c.scene, c.fabrics, lighting, opt);
      const ReferenceRenderResult res = rr.render(0);
      const double secs = seconds_since(t);
      reference_seconds += secs;
      ++references_rendered;
      std::cerr << " " << fmt(secs) << " s\n";
      ref = bench::CachedReference{res.image, res.kinds};
      bench::store_reference(cache_file, *ref);
    }
    return references.emplace(name, std::move(*ref)).first->second;
  };

  // One row: `method` on the GPU (with `bundle` for iwasaki) at both sizes against the reference.
  auto measure = [&](const Case& c, const LadderEntry& m, const std::string& label, const std::string& file_id,
                     std::shared_ptr<const IwasakiBundleData> bundle) {
    const bench::CachedReference* ref = &reference(c, m.thin_reference);
    std::vector<bool> surface(ref->kinds.size());
    for (size_t i = 0; i < surface.size(); ++i) surface[i] = ref->kinds[i] != PixelKind::background;
    const double exposure = auto_exposure(ref->image, surface);
    const std::string ref_png = "images/" + c.tag + (m.thin_reference ? "_thin" : "") + "_reference.png";
    if (!written.count(ref_png)) {
      write_image_png(ref->image, out / ref_png, exposure);
      written.insert(ref_png);
    }
    Row r;
    r.scene = c.scene_name, r.fabric = c.fabric_label, r.env = c.env, r.method = label;
    if (bundle) r.bundle_bytes = table_bytes(*bundle) + visibility_bytes(*bundle), r.tables = tables_summary(*bundle);
    r.visibility = gpu::uses_seed000_tables(m.name);
    const GpuFrame speed = render_gpu_frame(c.scene, c.fabrics, c.sgs, m.name, a.speed_width, a.speed_height,
                                            a.speed_frames, bundle);
    renderer = speed.renderer;
    r.ms = speed.median_ms, r.frames = speed.frames;
    const GpuFrame acc = render_gpu_frame(c.scene, c.fabrics, c.sgs, m.name, a.width, a.height, 0, bundle);
    r.image = "images/" + c.tag + "_" + file_id + ".png";
    write_image_png(acc.image, out / r.image, exposure);
    r.reference_image = ref_png;
    {
      const bench::ClothError e = bench::cloth_error(acc.image, ref->image, ref->kinds);
      r.rmse = e.relative_rmse, r.cloth_pixels = e.cloth_pixels;
      const Image em = bench::error_map(acc.image, ref->image, ref->kinds);
      std::vector<unsigned char> rgb(em.pixels.size() * 3);
      for (size_t i = 0; i < em.pixels.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) rgb[3 * i + ch] = static_cast<unsigned char>(std::lround(255.0 * em.pixels[i][ch]));
      r.error_image = "images/" + c.tag + "_" + file_id + "_error.png";
      bench::write_rgb8_png(out / r.error_image, em.width, em.height, rgb);
    }
    {
      std::vector<bool> lambertian(ref->kinds.size());
      for (size_t i = 0; i < lambertian.size(); ++i) lambertian[i] = ref->kinds[i] == PixelKind::lambertian;
      const bench::MaskedError e = bench::masked_error(acc.image, ref->image, lambertian);
      if (e.pixels) r.lambert_rmse = e.relative_rmse, r.lambert_ratio = e.brightness_ratio;
    }
    if (c.shadow && !m.thin_reference) {
      const bench::MaskedError in = bench::masked_error(acc.image, ref->image, c.shadow->shadow);
      const bench::MaskedError beside = bench::masked_error(acc.image, ref->image, c.shadow->band);
      r.shadow_pixels = in.pixels, r.band_pixels = beside.pixels;
      if (in.pixels) r.shadow_rmse = in.relative_rmse, r.shadow_ratio = in.brightness_ratio;
      if (beside.pixels) r.band_ratio = beside.brightness_ratio;
    }
    if (m.thin_reference) r.note = "against the thin-layer reference";
    std::cerr << "weft bench: " << c.tag << " " << label << ": " << fmt(r.ms) << " ms/frame at " << a.speed_width << "x"
              << a.speed_height << ", relative RMSE " << (r.rmse >= 0 ? fmt(r.rmse) : "n/a") << "\n";
    return r;
  };

  for (const auto& scene_name : a.scenes) {
    for (const auto& fabric_arg : a.fabrics) {
      for (const auto& env_arg : a.envs) {
        const Case c = make_case(scene_name, fabric_arg, env_arg);
        if (c.shadow && thin_occluder_case.empty()) {
          const auto& sun = c.shadow->sun;
          thin_occluder_case = "`" + c.env + "` (its brightest SG: axis (" + fmt(sun.axis.x, 2) + ", " +
                               fmt(sun.axis.y, 2) + ", " + fmt(sun.axis.z, 2) + "), λ = " + fmt(sun.sharpness) + "; on " +
                               c.fabric_label + ", " + std::to_string(c.shadow->shadow_pixels) +
                               " cloth pixels in its shadow, " + std::to_string(c.shadow->band_pixels) + " beside it)";
        }
        for (const auto& m : run) {
          if (!m.scenes.empty() && !m.scenes.count(scene_name)) continue;
          rows.push_back(measure(c, m, m.name, m.name, tables_for(m.name, c.scene, c.fabrics)));
          // "Model no more than a scene needs": the settings `weft bake --target-error` picks.
          if (m.name == "iwasaki" && a.target_error > 0) {
            IwasakiBakeOptions o = paper_bake();
            o.target_error = a.target_error;
            const auto bundle = bake(bake_key(c.scene, c.fabrics) + " target " + fmt(a.target_error), c.scene, c.fabrics, o);
            Row r = measure(c, m, target_label, "iwasaki_target", bundle);
            r.note = "bake_selection.h at error target " + fmt(a.target_error);
            rows.push_back(r);
          }
        }
      }
    }
  }

  // SG-count sweep on the first scene, against the map-lit reference.
  std::vector<SweepRow> sweep;
  std::string sweep_case;
  if (!a.sweep_sg_counts.empty()) {
    const Scene s = load_scene_preset(a.scenes.front(), assets / "scenes");
    std::map<std::string, Fabric> fabrics;
    for (const auto& o : s.objects)
      if (o.material == Material::cloth && !fabrics.count(o.fabric))
        fabrics.emplace(o.fabric, load_fabric_preset(o.fabric, assets / "fabrics"));
    const auto env_file = assets / "envmaps" / (s.environment + ".exr");
    auto map = std::make_shared<EnvMap>(load_env_map(env_file, NonFinitePolicy::clamp, nullptr));
    sweep_case = s.name + " / " + fabrics.begin()->first + " / " + s.environment + " (map-lit reference, 128x64 cells)";
    bench::InputHash h;
    h.add(bench::kReferenceCodeVersion).add_file(assets / "scenes" / (s.name + ".json")).add_file(env_file).add("map128");
    for (const auto& entry : std::filesystem::directory_iterator(assets / "scenes"))
      if (entry.path().extension() == ".bpt") h.add_file(entry.path());
    for (const auto& [name, f] : fabrics) h.add(name).add_file(assets / "fabrics" / (name + ".json"));
    h.add_number(a.width).add_number(a.height).add_number(a.tangent_samples);
    const auto cache_file = cache / (s.name + "_map_" + h.hex() + ".ref");
    auto ref = bench::load_reference(cache_file);
    if (ref) {
      ++references_cached;
    } else {
      std::cerr << "weft bench: map-lit reference " << s.name << " ..." << std::flush;
      ReferenceLighting lighting;
      lighting.samples = [map](int level) { return environment_samples(*map, 128 << level); };
      lighting.background = [map](const glm::dvec3& d) { return map->lookup(d); };
      ReferenceRenderOptions opt;
      opt.width = a.width, opt.height = a.height, opt.tangent_samples = a.tangent_samples;
      opt.check_convergence = false;
      const auto t = std::chrono::steady_clock::now();
      const ReferenceRenderResult res = ReferenceRenderer(s, fabrics, lighting, opt).render(0);
      reference_seconds += seconds_since(t);
      ++references_rendered;
      std::cerr << " " << fmt(seconds_since(t)) << " s\n";
      ref = bench::CachedReference{res.image, res.kinds};
      bench::store_reference(cache_file, *ref);
    }
    for (int k : a.sweep_sg_counts) {
      SgFitOptions fit;
      fit.count = k;
      const SgLighting sgs = fit_sgs(*map, fit);
      for (const auto& m : run) {
        if (!m.scenes.empty() && !m.scenes.count(s.name)) continue;
        if (m.thin_reference) continue;  // the map-lit reference has opaque cloth
        SweepRow r{m.name, k, 0.0, 0.0};
        r.ms = render_gpu_frame(s, fabrics, sgs, m.name, a.speed_width, a.speed_height, 5, tables_for(m.name, s, fabrics)).median_ms;
        const GpuFrame acc = render_gpu_frame(s, fabrics, sgs, m.name, a.width, a.height, 0, tables_for(m.name, s, fabrics));
        r.rmse = bench::cloth_error(acc.image, ref->image, ref->kinds).relative_rmse;
        std::cerr << "weft bench: sweep " << m.name << " K=" << k << ": " << fmt(r.ms) << " ms, relative RMSE "
                  << fmt(r.rmse) << "\n";
        sweep.push_back(r);
      }
    }
    std::ofstream csv(out / "sweep_sg_count.csv");
    csv << "method,sg_count,ms_per_frame,relative_rmse_vs_map\n";
    for (const auto& r : sweep) csv << r.method << "," << r.sg_count << "," << fmt(r.ms, 6) << "," << fmt(r.rmse, 6) << "\n";
  }

  // iwasaki's bake knobs, one at a time from the paper-default bundle, on the first scene with
  // its own fabric and map: each point is a fresh in-memory bake of the changed half of the
  // bundle (tables, or visibility + κ), the other half shared with the paper-default bundle.
  std::vector<KnobSweep> knob_sweeps;
  std::string knob_case;
  KnobRow knob_default;
  if (!a.sweep_tangent_samples.empty() || !a.sweep_svd_errors.empty() || !a.sweep_sdf_resolutions.empty() ||
      !a.sweep_sdf_supersamples.empty()) {
    const Case c = make_case(a.scenes.front(), "scene", "scene");
    knob_case = c.scene_name + " / " + c.fabric_label + " / " + c.env;
    const LadderEntry iw{"iwasaki", {}, false};
    std::shared_ptr<const IwasakiBundleData> base;
    if (has_iwasaki) {
      base = tables_for("iwasaki", c.scene, c.fabrics);
      knob_default.value = "paper default";
      knob_default.table_bytes = table_bytes(*base), knob_default.visibility_bytes = visibility_bytes(*base);
      knob_default.tables = tables_summary(*base);
      const bench::CachedReference& ref = reference(c, false);
      knob_default.ms =
          render_gpu_frame(c.scene, c.fabrics, c.sgs, "iwasaki", a.speed_width, a.speed_height, 5, base).median_ms;
      const GpuFrame acc = render_gpu_frame(c.scene, c.fabrics, c.sgs, "iwasaki", a.width, a.height, 0, base);
      knob_default.rmse = bench::cloth_error(acc.image, ref.image, ref.kinds).relative_rmse;
    }
    auto knob_sweep = [&](const std::string& knob, const std::string& file, const std::string& default_value,
                          const std::vector<std::string>& values, const std::function<void(size_t, IwasakiBakeOptions&)>& set,
                          bool tables_half) {
      KnobSweep ks{knob, file, default_value, {}, ""};
      if (values.empty()) return;
      if (!has_iwasaki) ks.skipped = "iwasaki is not in the GPU runtime of this build";
      else if (!tables_half && base->visibility.empty())
        ks.skipped = "no cloth object of " + c.scene_name + " is occluded: the bundle stores no visibility, so the SDF "
                     "resolution changes nothing (put an occluded scene first, e.g. --scenes pillow)";
      for (size_t i = 0; i < values.size() && ks.skipped.empty(); ++i) {
        IwasakiBakeOptions o = paper_bake();
        set(i, o);
        (tables_half ? o.bake_visibility : o.bake_tables) = false;
        std::cerr << "weft bench: sweep iwasaki " << knob << " = " << values[i] << ": baking ..." << std::flush;
        const auto t = std::chrono::steady_clock::now();
        IwasakiBundleData half = bake_iwasaki(c.scene, c.fabrics, o);
        KnobRow r;
        r.value = values[i];
        r.bake_s = seconds_since(t);
        auto bundle = std::make_shared<IwasakiBundleData>();
        bundle->tables = tables_half ? std::move(half.tables) : base->tables;
        if (tables_half) bundle->visibility = base->visibility, bundle->kappa = base->kappa;
        else bundle->visibility = std::move(half.visibility), bundle->kappa = std::move(half.kappa);
        r.table_bytes = table_bytes(*bundle), r.visibility_bytes = visibility_bytes(*bundle);
        r.tables = tables_summary(*bundle);
        const bench::CachedReference& ref = reference(c, false);
        r.ms = render_gpu_frame(c.scene, c.fabrics, c.sgs, iw.name, a.speed_width, a.speed_height, 5, bundle).median_ms;
        const GpuFrame acc = render_gpu_frame(c.scene, c.fabrics, c.sgs, iw.name, a.width, a.height, 0, bundle);
        r.rmse = bench::cloth_error(acc.image, ref.image, ref.kinds).relative_rmse;
        std::cerr << " " << fmt(r.bake_s) << " s; " << fmt(r.ms) << " ms/frame, relative RMSE " << fmt(r.rmse) << "\n";
        ks.rows.push_back(r);
      }
      std::ofstream csv(out / file);
      csv << "knob,value,ms_per_frame,relative_rmse,table_bytes,visibility_bytes,bake_seconds,tables\n";
      for (const auto& r : ks.rows)
        csv << knob << "," << r.value << "," << fmt(r.ms, 6) << "," << fmt(r.rmse, 6) << "," << r.table_bytes << ","
            << r.visibility_bytes << "," << fmt(r.bake_s, 4) << ",\"" << r.tables << "\"\n";
      if (!csv) throw std::runtime_error("cannot write " + (out / file).string());
      knob_sweeps.push_back(std::move(ks));
    };
    auto texts = [](const auto& v) {
      std::vector<std::string> t;
      for (const auto& x : v) t.push_back(fmt(double(x), 4));
      return t;
    };
    std::string paper_samples;
    for (const auto& [name, f] : c.fabrics) {
      const auto n = paper_tangent_samples(f);
      paper_samples += (paper_samples.empty() ? "" : ", ") + std::to_string(n[0]) + "+" + std::to_string(n[1]);
    }
    knob_sweep("tangent samples per thread", "sweep_tangent_samples.csv", paper_samples, texts(a.sweep_tangent_samples),
               [&](size_t i, IwasakiBakeOptions& o) { o.tangent_samples = {a.sweep_tangent_samples[i], a.sweep_tangent_samples[i]}; },
               true);
    knob_sweep("SVD error", "sweep_svd_error.csv", fmt(BakeSettings{}.svd_error), texts(a.sweep_svd_errors),
               [&](size_t i, IwasakiBakeOptions& o) { o.svd_error = a.sweep_svd_errors[i]; }, true);
    knob_sweep("SDF resolution", "sweep_sdf_resolution.csv", std::to_string(paper_bake().visibility.resolution),
               texts(a.sweep_sdf_resolutions),
               [&](size_t i, IwasakiBakeOptions& o) { o.visibility.resolution = a.sweep_sdf_resolutions[i]; }, false);
    knob_sweep("SDF supersampling (rays per cell side)", "sweep_sdf_supersample.csv",
               std::to_string(paper_bake().visibility.supersample), texts(a.sweep_sdf_supersamples),
               [&](size_t i, IwasakiBakeOptions& o) { o.visibility.supersample = a.sweep_sdf_supersamples[i]; }, false);
  }
  // Stability table: every CPU method × stress case, against the reference.
  struct StabilityCell {
    std::string method, stress, notes;
    bench::StressResult r;
  };
  std::vector<StabilityCell> stability;
  if (!a.no_stability && a.stress_points > 0) {
    const auto cases = bench::stress_cases(assets / "fabrics", a.stress_points);
    std::vector<std::vector<glm::dvec3>> refs;
    for (const auto& c : cases) refs.push_back(bench::stress_reference(c));
    for (const auto& m : bench::cpu_methods())
      for (size_t i = 0; i < cases.size(); ++i)
        stability.push_back({m.name, cases[i].name, cases[i].notes, bench::run_stress(m, cases[i], &refs[i])});
  }
  const double total = seconds_since(t_start);

  // CSV
  {
    std::ofstream csv(out / "results.csv");
    csv << "scene,fabric,env,method,speed_width,speed_height,ms_per_frame,frames,width,height,relative_rmse,cloth_pixels,"
           "renderer,note,bundle_bytes,shadow_pixels,shadow_relative_rmse,shadow_brightness_ratio,band_brightness_ratio,"
           "lambert_relative_rmse,lambert_brightness_ratio\n";
    for (const auto& r : rows)
      csv << r.scene << "," << r.fabric << "," << r.env << "," << r.method << "," << a.speed_width << "," << a.speed_height
          << "," << fmt(r.ms, 6) << "," << r.frames << "," << a.width << "," << a.height << ","
          << (r.rmse >= 0 ? fmt(r.rmse, 6) : "") << "," << r.cloth_pixels << ",\"" << renderer << "\",\"" << r.note
          << "\"," << (r.bundle_bytes ? std::to_string(r.bundle_bytes) : "") << ","
          << (r.shadow_pixels ? std::to_string(r.shadow_pixels) : "") << "," << (r.shadow_rmse >= 0 ? fmt(r.shadow_rmse, 6) : "")
          << "," << (r.shadow_ratio >= 0 ? fmt(r.shadow_ratio, 6) : "") << ","
          << (r.band_ratio >= 0 ? fmt(r.band_ratio, 6) : "") << "," << (r.lambert_rmse >= 0 ? fmt(r.lambert_rmse, 6) : "")
          << "," << (r.lambert_ratio >= 0 ? fmt(r.lambert_ratio, 6) : "") << "\n";
    if (!csv) throw std::runtime_error("cannot write " + (out / "results.csv").string());
  }
  std::vector<bench::ChartPoint> points;
  for (const auto& r : rows)
    if (r.rmse > 0) points.push_back({r.method, r.ms, r.rmse});
  bench::write_chart_png(out / "chart.png", points, "WEFT BENCH " + std::to_string(a.speed_width) + "X" +
                                                          std::to_string(a.speed_height) + " (" + renderer + ")");
  const auto markers = bench::chart_markers(points);

  // Report
  std::ofstream md(out / "report.md");
  md << "# Weft bench: speed against accuracy\n\n";
  md << "Regenerate: `" << command_line(a, a.quick) << "` (" << fmt(total, 4)
     << " s this run; " << references_rendered << " reference renders, " << fmt(reference_seconds, 4) << " s, "
     << references_cached << " from the cache).\n\n";
  md << "GL renderer: `" << renderer << "`. Speed: median of " << a.speed_frames << " frames after one warm-up frame, "
     << "glFinish included, at " << a.speed_width << "x" << a.speed_height << ". Accuracy: relative RMSE "
     << "`sqrt(mean((x-r)^2))/mean(r)` over the cloth pixels at " << a.width << "x" << a.height << " against `reference` "
     << "under the same " << a.sg_count << " fitted SGs (SG grid " << a.sg_grid << "x" << 2 * a.sg_grid << ", "
     << a.tangent_samples << " tangent samples per thread). Times on llvmpipe: compare ratios within one run.\n\n";
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
  // The target-error point against the paper default, case by case, from the numbers above.
  if (run_iwasaki && a.target_error > 0) {
    md << "\n## `weft bake --target-error " << fmt(a.target_error) << "` against the paper's settings\n\n"
       << "`" << target_label << "`: tables baked with the settings bake_selection.h picks for error target "
       << fmt(a.target_error) << " (tangent samples, λ levels, SVD error = target; grids as the paper row). Cost: ms/frame "
       << "and bundle bytes (tables + visibility PCA). The selection holds each knob's own error (on its probe of the "
          "fabric's radiance) under the target separately; the image error compounds them with the SG and visibility "
          "approximations, so a target looser than the default settings' own knob errors (SVD: 0.01) can cost image error.\n\n"
       << "| case | paper: ms | target: ms | paper: RMSE | target: RMSE | paper: bytes | target: bytes | verdict |\n"
       << "|---|---|---|---|---|---|---|---|\n";
    for (const auto& p : rows) {
      if (p.method != "iwasaki") continue;
      for (const auto& t : rows) {
        if (t.method != target_label || t.scene != p.scene || t.fabric != p.fabric || t.env != p.env) continue;
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
        md << "| " << p.scene << " / " << p.fabric << " / " << p.env << " | " << fmt(p.ms) << " | " << fmt(t.ms) << " | "
           << fmt(p.rmse) << " | " << fmt(t.rmse) << " | " << p.bundle_bytes << " | " << t.bundle_bytes << " | " << verdict
           << " |\n";
        md << "| | tables: " << p.tables << " | tables: " << t.tables << " | | | | | |\n";
      }
    }
  }
  md << "\n## Images (method | reference | error: black 0, red 0.5, yellow ≥ 1 of the mean cloth radiance)\n\n";
  md << "| case | method | reference | error |\n|---|---|---|---|\n";
  for (const auto& r : rows)
    md << "| " << r.scene << " / " << r.fabric << " / " << r.env << " / " << r.method << " | ![](" << r.image
       << ") | ![](" << r.reference_image << ") | " << (r.error_image.empty() ? "n/a" : "![](" + r.error_image + ")")
       << " |\n";
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
       << "row: tables grid " << (a.bake_grid > 0 ? a.bake_grid : 48) << ", SDF " << paper_bake().visibility.resolution
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
  md << "\n## Stability: method × stress case → error\n\n";
  if (stability.empty()) {
    md << "Not run (--no-stability).\n";
  } else {
    md << "C++ evaluation of each method at " << a.stress_points << " points per case (render/bench/stability.h), "
       << "relative RMSE against the canonical model by quadrature (1 % tolerance) (for `thin`: (1-α)·canonical + the thin layer "
       << "integrated exactly). iwasaki and mizutani read tables baked for the stress fabrics at grid " << bench::kStressTableGrid
       << " with the paper's tangent samples (iwasaki without visibility), so their error includes those few samples "
          "against the reference's 16. NaN/Inf/negative counts must be 0 (tests/method_stability_test.cpp asserts it at "
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
       << ". Only the methods marked with visibility shade with it (seed 000's linearised SDF per SG, baked for the "
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
      md << "| " << r->fabric << " / " << r->env << " | " << r->method << " | " << (r->visibility ? "seed 000 SDF" : "none") << " | " << fmt(r->rmse) << " | "
         << fmt(r->shadow_rmse) << " | " << fmt(r->shadow_ratio) << " | " << (r->band_ratio >= 0 ? fmt(r->band_ratio) : "n/a")
         << " |\n";
  }
  md << "\n## Missing\n\n";
  for (const auto& m : missing) md << "- `" << m << "`: not in the GPU runtime of this build (`weft render --method` lists what is).\n";
  if (a.sweep_sg_counts.empty() && knob_sweeps.empty())
    md << "- Cost-knob sweeps: none asked for this run (`--sweep-sg-counts`, `--sweep-tangent-samples`, "
          "`--sweep-svd-error`, `--sweep-sdf-resolution`).\n";
  if (a.target_error <= 0 || !run_iwasaki)
    md << "- The `weft bake --target-error` point: not measured this run (needs `iwasaki` and `--target-error` > 0).\n";
  md << "- The SVD knob is swept as its error target (ranks follow from it per table; the tables column gives the mean); "
        "the κ table and the λ levels are not swept; the sweeps are tables and CSVs, not drawn on the chart. The stability table's iwasaki runs without visibility, on tables of "
        "grid " << bench::kStressTableGrid << " (not 48) with the paper's tangent samples; mizutani likewise.\n";
  if (!md) throw std::runtime_error("cannot write " + (out / "report.md").string());

  std::cout << "{\"out\":\"" << a.out << "\",\"rows\":" << rows.size() << ",\"seconds\":" << fmt(total, 4)
            << ",\"csv\":\"" << (out / "results.csv").string() << "\",\"chart\":\"" << (out / "chart.png").string()
            << "\",\"report\":\"" << (out / "report.md").string() << "\"}\n";
  return 0;
}

}  // namespace

CommandAction add_bench_command(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* sub = app.add_subcommand("bench", "Speed against accuracy for every GPU method: CSV, chart, report");
  sub->add_flag("--quick", a->quick,
                "Smoke run: swatch/linen_plain at 64x48, reference SG grid 4, 8 tangent samples, "
                "iwasaki tables grid 12 and SDF 16, 2 stress points per case; the target-error row, and "
                "sweeps of tangent samples 1,3 and SVD error 0.1,0.01 unless given");
  sub->add_option("--out", a->out, "Output folder (results.csv, chart.png, report.md, images/)")->capture_default_str();
  sub->add_option("--cache", a->cache, "Reference cache folder (default: OUT/reference-cache)");
  sub->add_option("--scenes", a->scenes, "Scenes")->delimiter(',')->capture_default_str();
  sub->add_option("--fabrics", a->fabrics, "Fabric presets ('scene': each scene's own)")->delimiter(',')->capture_default_str();
  sub->add_option("--envs", a->envs, "Environment maps ('scene': each scene's own)")->delimiter(',')->capture_default_str();
  sub->add_option("--methods", a->methods, "GPU methods (default: all available)")->delimiter(',');
  sub->add_option("--speed-width", a->speed_width, "Speed: frame width")->capture_default_str();
  sub->add_option("--speed-height", a->speed_height, "Speed: frame height")->capture_default_str();
  sub->add_option("--speed-frames", a->speed_frames, "Speed: frames timed after the warm-up")->capture_default_str();
  sub->add_option("--width", a->width, "Accuracy: frame width")->capture_default_str();
  sub->add_option("--height", a->height, "Accuracy: frame height")->capture_default_str();
  sub->add_option("--sg-grid", a->sg_grid, "Reference: SG grid N (N x 2N cells per SG)")->capture_default_str();
  sub->add_option("--tangent-samples", a->tangent_samples, "Reference: tangent samples per thread")->capture_default_str();
  sub->add_option("--sg-count", a->sg_count, "SGs fitted to each map")->capture_default_str();
  sub->add_option("--stress-points", a->stress_points, "Stability table: points per stress case")->capture_default_str();
  sub->add_flag("--no-stability", a->no_stability, "Skip the stability table");
  sub->add_option("--sweep-sg-counts", a->sweep_sg_counts,
                  "SG counts to sweep on the first scene (e.g. 1,2,5,10,20,40), against its map-lit reference")
      ->delimiter(',');
  sub->add_option("--bake-grid", a->bake_grid,
                  "iwasaki tables: xi/omega grids NxN (0: the paper's 48; --quick uses 12)")
      ->capture_default_str();
  sub->add_option("--target-error", a->target_error,
                  "Add an 'iwasaki (target E)' row per case, baked with the settings `weft bake --target-error E` "
                  "picks, next to the paper-default iwasaki row (0: off)")
      ->capture_default_str();
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
  return [a] { return run_bench(*a); };
}

}  // namespace weft
