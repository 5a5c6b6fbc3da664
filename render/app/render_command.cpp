// `weft render`: one frame of a showroom scene to EXR (linear radiance) plus a tone-mapped PNG
// beside it. Methods: `reference` (ground truth of DESIGN.md §2 by ray casting and quadrature).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/gpu_render.h"
#include "gpu/scene_renderer.h"
#include "app/iwasaki_bake.h"
#include "runtime/iwasaki_bundle.h"
#include "runtime/scene_bundle.h"
#include "gpu/egl_context.h"
#include "app/progress_bar.h"
#include "app/commands.h"
#include "core/fabric.h"
#include "image/image.h"
#include "lighting/env_map.h"
#include "lighting/sg_fit.h"
#include "lighting/sg_set_io.h"
#include "reference/environment_samples.h"
#include "reference/scene_render.h"
#include "scene/scene.h"

namespace weft {

namespace {

struct RenderArgs {
  std::string scene = "swatch";
  std::string fabric;  // empty: each cloth object's own
  std::string env;     // empty: the scene's
  std::string method = "reference";
  std::string lighting = "sg";
  std::string sgs_file;
  std::string out;
  int width = 320, height = 240;
  int sg_grid = 8;
  int map_width = 128;
  int sg_count = 10;
  int tangent_samples = 16;
  int check_stride = 6;
  bool no_check = false;
  double exposure = 0.0;  // 0: automatic
  int timed_frames = 20;
  std::string bundle;  // iwasaki: scene and tables from a baked bundle instead of baking in memory
};

std::filesystem::path png_beside(const std::filesystem::path& exr) {
  auto p = exr;
  p.replace_extension(".png");
  return p;
}

int run_render(const RenderArgs& a) {
  {
    std::string all = "reference";
    bool known = a.method == "reference";
    for (const auto& m : gpu::method_names()) known = known || m == a.method, all += ", " + m;
    if (!known) throw UsageError("--method: '" + a.method + "' is not available (available: " + all + ")");
  }
  if (!a.bundle.empty() && !gpu::reads_seed000_tables(a.method))
    throw UsageError("--bundle: only with --method iwasaki, iwasaki_vertex or mizutani");
  if (a.lighting != "sg" && a.lighting != "map") throw UsageError("--lighting: must be 'sg' or 'map'");
  if (a.width < 1 || a.height < 1 || a.width > 8192 || a.height > 8192)
    throw UsageError("--width/--height: must be within 1..8192");
  if (a.sg_grid < 1 || a.sg_grid > 512) throw UsageError("--sg-grid: must be within 1..512");
  if (a.map_width < 4 || a.map_width > 4096 || a.map_width % 2)
    throw UsageError("--map-width: must be even and within 4..4096");
  if (a.sg_count < 1 || a.sg_count > 64) throw UsageError("--sg-count: must be within 1..64");
  if (a.tangent_samples < 1 || a.tangent_samples > 4096) throw UsageError("--tangent-samples: must be within 1..4096");
  if (a.check_stride < 1) throw UsageError("--check-stride: must be ≥ 1");
  if (!(a.exposure >= 0.0) || !std::isfinite(a.exposure)) throw UsageError("--exposure: must be ≥ 0 (0: automatic)");
  const std::filesystem::path out(a.out);
  if (out.extension() != ".exr") throw UsageError("--out: must name an .exr file, got '" + a.out + "'");

  Scene scene;
  try {
    scene = load_scene_preset(a.scene, assets_dir() / "scenes");
  } catch (const SceneError& e) {
    throw UsageError(e.what());
  }
  for (const auto& obj : scene.objects)
    if (obj.repair.degenerate_triangles_dropped > 0)
      std::cerr << "weft render: mesh " << scene.name << "/" << obj.name << ": dropped "
                << obj.repair.degenerate_triangles_dropped << " degenerate triangles\n";
  std::shared_ptr<const IwasakiBundleData> iwasaki;
  if (!a.bundle.empty()) {
    // The bundle's scene, fabrics and seed 000 tables; the lighting still comes from the options.
    try {
      const auto reader = bundle::BundleReader::open(a.bundle);
      SceneBundle sb = read_scene_bundle(reader);
      std::map<size_t, size_t> vertices;
      for (size_t i = 0; i < sb.scene.objects.size(); ++i) vertices[i] = sb.scene.objects[i].mesh.positions.size();
      if (!has_iwasaki_sections(reader)) throw UsageError("--bundle: " + a.bundle + " has no seed 000 tables (weft bake without --no-tables)");
      iwasaki = std::make_shared<IwasakiBundleData>(read_iwasaki_sections(reader, vertices));
      scene = std::move(sb.scene);
    } catch (const bundle::BundleError& e) {
      throw UsageError(std::string("--bundle: ") + e.what());
    }
  }
  if (!a.fabric.empty())
    for (auto& obj : scene.objects)
      if (obj.material == Material::cloth) obj.fabric = a.fabric;
  std::map<std::string, Fabric> fabrics;
  for (const auto& obj : scene.objects)
    if (obj.material == Material::cloth && !fabrics.count(obj.fabric))
      fabrics.emplace(obj.fabric, load_fabric_preset(obj.fabric, assets_dir() / "fabrics"));
  const std::string env = a.env.empty() ? scene.environment : a.env;

  const auto env_file = assets_dir() / "envmaps" / (env + ".exr");
  if (!std::filesystem::exists(env_file)) throw UsageError("--env: no environment map " + env_file.string());
  EnvMapRepairs repairs;
  std::shared_ptr<EnvMap> map;
  try {
    map = std::make_shared<EnvMap>(load_env_map(env_file, NonFinitePolicy::clamp, &repairs));
  } catch (const EnvMapError& e) {
    throw UsageError(e.what());
  }
  if (repairs.total() > 0)
    std::cerr << "weft render: environment " << env << ": clamped " << repairs.nan << " NaN, " << repairs.infinite
              << " infinite and " << repairs.negative << " negative channel values to 0\n";

  ReferenceLighting lighting;
  if (a.lighting == "map") {
    if (!a.sgs_file.empty()) throw UsageError("--sgs: only with --lighting sg");
    const int base = a.map_width;
    lighting.samples = [map, base](int level) { return environment_samples(*map, base << level); };
    lighting.background = [map](const glm::dvec3& d) { return map->lookup(d); };
    lighting.description = "map " + env + " as " + std::to_string(base) + "x" + std::to_string(base / 2) +
                           " stratified cells";
  } else {
    if (!a.sgs_file.empty()) {
      try {
        lighting.sgs = load_sg_set(a.sgs_file);
      } catch (const SgSetError& e) {
        throw UsageError(std::string("--sgs: ") + e.what());
      }
      lighting.description = std::to_string(lighting.sgs.size()) + " SGs from " + a.sgs_file;
    } else {
      const auto t = std::chrono::steady_clock::now();
      SgFitOptions fit;
      fit.count = a.sg_count;
      lighting.sgs = fit_sgs(*map, fit);
      lighting.description = std::to_string(lighting.sgs.size()) + " SGs fitted to " + env + " (" +
                             std::to_string(std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count())
                                 .substr(0, 4) +
                             " s)";
    }
    lighting.background = [sgs = lighting.sgs](const glm::dvec3& d) { return evaluate(sgs, d); };
  }

  if (gpu::uses_seed000_tables(a.method) && !iwasaki) {
    std::cerr << "weft render: baking seed 000's tables in memory (weft bake stores them in a bundle)\n";
    iwasaki = std::make_shared<IwasakiBundleData>(bake_iwasaki(scene, fabrics, IwasakiBakeOptions{}));
  }
  if (a.method != "reference") {
    GpuFrame f;
    try {
      f = render_gpu_frame(scene, fabrics, lighting.sgs, a.method, a.width, a.height, a.timed_frames, iwasaki);
    } catch (const gpu::GpuError& e) {
      std::cerr << "weft render: " << e.what() << "\n";
      return 1;
    }
    write_exr(f.image, out);
    std::vector<bool> drawn(f.image.pixels.size());  // the GPU frame clears the background to 0
    for (size_t i = 0; i < drawn.size(); ++i) drawn[i] = f.image.pixels[i] != glm::dvec3(0.0);
    write_png(f.image, png_beside(out), a.exposure > 0.0 ? a.exposure : auto_exposure(f.image, drawn));
    nlohmann::ordered_json j;
    j["scene"] = scene.name;
    j["method"] = a.method;
    j["width"] = a.width;
    j["height"] = a.height;
    j["renderer"] = f.renderer;
    j["median_ms"] = f.median_ms;
    j["frames"] = f.frames;
    j["out"] = a.out;
    std::cout << j.dump() << "\n";
    return 0;
  }

  ReferenceRenderOptions opt;
  opt.width = a.width;
  opt.height = a.height;
  opt.sg_grid = a.sg_grid;
  opt.tangent_samples = a.tangent_samples;
  opt.check_stride = a.check_stride;
  opt.check_convergence = !a.no_check;
  ProgressBar bar("weft render " + scene.name);
  opt.progress = [&bar](double f) { bar(f); };

  std::cerr << "weft render: scene " << scene.name << ", " << a.width << "x" << a.height << ", lighting "
            << lighting.description
            << (a.lighting == "sg" ? ", SG grid " + std::to_string(a.sg_grid) + "x" + std::to_string(2 * a.sg_grid) + " per SG, "
                                   : std::string(", "))
            << a.tangent_samples << " tangent samples per thread\n";
  const ReferenceRenderer renderer(scene, fabrics, lighting, opt);
  const ReferenceRenderResult r = renderer.render(0);
  write_exr(r.image, out);
  std::vector<bool> surface(r.kinds.size());
  for (size_t i = 0; i < r.kinds.size(); ++i) surface[i] = r.kinds[i] != PixelKind::background;
  const double exposure = a.exposure > 0.0 ? a.exposure : auto_exposure(r.image, surface);
  write_png(r.image, png_beside(out), exposure);

  nlohmann::ordered_json j;
  j["scene"] = scene.name;
  j["method"] = a.method;
  j["lighting"] = a.lighting;
  j["environment"] = env;
  j["width"] = a.width;
  j["height"] = a.height;
  j["lighting_description"] = lighting.description;
  if (a.lighting == "sg") j["sg_grid"] = a.sg_grid;
  else j["map_width"] = a.map_width;
  j["tangent_samples"] = a.tangent_samples;
  j["seconds"] = r.seconds;
  j["exr"] = out.string();
  j["png"] = png_beside(out).string();
  j["png_exposure"] = exposure;
  if (opt.check_convergence) {
    const auto& c = r.convergence;
    j["convergence"] = {{"compared_with", "2x lighting resolution and 2x tangent samples"},
                        {"check_stride", a.check_stride},
                        {"pixels_checked", c.pixels_checked},
                        {"relative_rmse", c.relative_rmse},
                        {"cloth_relative_rmse", c.cloth_relative_rmse},
                        {"max_pixel_change", c.max_pixel_change},
                        {"seconds", c.seconds}};
    std::cerr << "weft render: done in " << r.seconds << " s; convergence (1 in " << a.check_stride * a.check_stride
              << " pixels at twice the lighting resolution and tangent samples): relative RMSE " << 100 * c.relative_rmse << " % (cloth "
              << 100 * c.cloth_relative_rmse << " %), max pixel change " << 100 * c.max_pixel_change << " %\n";
  } else {
    std::cerr << "weft render: done in " << r.seconds << " s (convergence not checked)\n";
  }
  std::cout << j.dump() << "\n";
  return 0;
}

}  // namespace

CommandAction add_render_command(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* sub = app.add_subcommand("render", "Render one frame of a showroom scene to EXR (+ tone-mapped PNG)");
  sub->add_option("--scene", a->scene, "Scene name (assets/scenes/NAME.json): swatch, pillow, drape, teapot, curtain")
      ->capture_default_str();
  sub->add_option("--fabric", a->fabric, "Fabric preset for every cloth object (default: the scene's)");
  sub->add_option("--env", a->env, "Environment map name (default: the scene's)");
  sub->add_option("--method", a->method, "Method: reference (ground truth of DESIGN.md §2, CPU) or a GPU method: sgpoint, iwasaki, iwasaki_vertex, mizutani, sheen, mdfrot, thin (mizutani bakes its tables first)")->capture_default_str();
  sub->add_option("--lighting", a->lighting, "sg: spherical Gaussians; map: the environment map itself")
      ->capture_default_str();
  sub->add_option("--sgs", a->sgs_file,
                  "SG lighting from a JSON file (as `weft fit --out` writes); default: fit the environment map");
  sub->add_option("--sg-count", a->sg_count, "SGs to fit to the map when no --sgs is given")->capture_default_str();
  sub->add_option("--out", a->out, "Output .exr (a .png is written beside it)")->required();
  sub->add_option("--width", a->width, "Image width")->capture_default_str();
  sub->add_option("--height", a->height, "Image height")->capture_default_str();
  sub->add_option("--sg-grid", a->sg_grid, "Reference: SG quadrature grid N (N x 2N cells per SG)")
      ->capture_default_str();
  sub->add_option("--map-width", a->map_width, "Reference, --lighting map: cells across the map (W x W/2)")
      ->capture_default_str();
  sub->add_option("--tangent-samples", a->tangent_samples, "Reference: tangent samples per thread N_j")
      ->capture_default_str();
  sub->add_option("--check-stride", a->check_stride,
                  "Convergence check: re-render every Nth pixel (in x and y) at twice the lighting resolution and tangent samples")
      ->capture_default_str();
  sub->add_flag("--no-convergence-check", a->no_check, "Skip the convergence check");
  sub->add_option("--bundle", a->bundle, "iwasaki, iwasaki_vertex, mizutani: take the scene and seed 000 tables from this bundle (weft bake) instead of baking them");
  sub->add_option("--frames", a->timed_frames, "GPU methods: frames timed after a warm-up (median reported)")
      ->capture_default_str();
  sub->add_option("--exposure", a->exposure, "PNG: exposure before the 1-exp(-x) tone curve and sRGB (0: automatic, from the mean of the surfaces)")
      ->capture_default_str();
  return [a] { return run_render(*a); };
}

}  // namespace weft
