// `weft render`: one frame of a showroom scene to EXR (linear radiance) plus a tone-mapped PNG
// beside it, with `reference` (ground truth of docs/design.md §2 by ray casting and quadrature) or a
// GPU method (frame/ holds the work).
#include <cmath>
#include <iostream>

#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/progress_bar.h"
#include "bake/scene/scene_bake.h"
#include "frame/frame_files.h"
#include "frame/frame_inputs.h"
#include "gpu/egl_context.h"
#include "frame/frame_render.h"
#include "gpu/scene_renderer.h"
#include "methods/registry.h"
#include "runtime/visibility_mask.h"
#include "scene/weave_scale.h"

namespace weft {

namespace {

struct RenderArgs {
  std::string scene = "swatch";
  std::string fabric;  // empty: each cloth object's own
  std::string env;     // empty: the scene's
  std::string method = "reference";
  std::string lighting = "sg";
  std::string sgs_file, out;
  int width = 320, height = 240, sg_grid = 8, map_width = 128, sg_count = 10, check_stride = 6, timed_frames = 20;
  int tangent_samples = 32;  // docs/design.md §2: the reference converges in N_j ≥ 32
  int supersample = 0, table_grid = 0;  // 0: 4 with --weave (else 1); 0: the paper's 48×48 tables baked in memory
  bool no_check = false, weave = false;
  std::string weave_terms = "pixel", backdrop = "showroom";
  double exposure = 0.0, exposure_bias = 0.0;  // exposure 0: automatic
  std::string bundle;  // iwasaki: scene and tables from a baked bundle instead of baking in memory
  std::string camera = "scene";  // or "closeup", or "EYE:TARGET[:FOV]"
};

int run_render(const RenderArgs& a) {
  {
    std::string all = "reference";
    bool known = a.method == "reference";
    for (const auto& m : methods::method_names()) known = known || m == a.method, all += ", " + m;
    if (!known) throw UsageError("--method: '" + a.method + "' is not available (available: " + all + ")");
  }
  const methods::RuntimeMethod* method = methods::find_method(a.method);  // null: the reference
  if (!a.bundle.empty() && !(method && method->reads_weighting_tables()))
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
  if (!std::isfinite(a.exposure_bias) || std::abs(a.exposure_bias) > 20) throw UsageError("--exposure-bias: must be within -20..20 EV");
  if (a.backdrop != "showroom" && a.backdrop != "measure") throw UsageError("--backdrop: must be 'showroom' or 'measure'");
  if (a.supersample < 0 || a.supersample > 16) throw UsageError("--supersample: must be within 1..16");
  if (std::filesystem::path(a.out).extension() != ".exr")
    throw UsageError("--out: must name an .exr file, got '" + a.out + "'");

  FrameInputs in;
  ReferenceLighting lighting;
  try {
    in = load_frame_inputs({assets_dir(), a.scene, a.fabric, a.env, a.bundle});
    lighting = frame_lighting(in, {a.lighting, a.sgs_file, a.sg_count, a.map_width});
  } catch (const FrameInputError& e) {
    throw UsageError(e.what());
  }
  if (a.camera == "closeup") in.scene.camera = closeup_camera(in.scene, in.fabrics, a.height);
  else if (a.camera != "scene") in.scene.camera = parse_camera(a.camera, in.scene.camera, "--camera");
  if (method && method->needs_weighting_tables() && !in.shading) {
    std::cerr << "weft render: baking the weighting tables in memory (weft bake stores them in a bundle)\n";
    ShadingDataBakeOptions o;
    o.grid = a.table_grid, o.progress = open_progress_bar;
    if (method->reads_visibility_masks()) o.mask_resolution = kMaskResolution;
    in.shading = std::make_shared<ShadingData>(bake_shading_data(in.scene, in.fabrics, o));
  }
  const FrameFileOptions files{a.method, a.out, a.width, a.height, a.exposure, a.exposure_bias};
  if (a.method != "reference") {
    GpuFrame f;
    try {
      const gpu::Backdrop backdrop = a.backdrop == "showroom" ? gpu::Backdrop::showroom : gpu::Backdrop::measure;
      f = render_gpu_frame(in.scene, in.fabrics, lighting.sgs, a.method, a.width, a.height, a.timed_frames, in.shading, backdrop, a.weave, a.weave_terms == "pixel");
    } catch (const gpu::GpuError& e) {
      std::cerr << "weft render: " << e.what() << "\n";
      return 1;
    }
    write_gpu_frame(in, f, files);
    return 0;
  }
  ProgressBar bar("weft render " + in.scene.name);
  render_reference_frame(in, lighting, files,
                         {a.lighting, a.sg_grid, a.map_width, a.tangent_samples, a.check_stride, !a.no_check, a.weave,
                          a.supersample > 0 ? a.supersample : (a.weave ? 4 : 1)},
                         [&bar](double f) { bar(f); });
  return 0;
}

}  // namespace

CommandAction add_render_command(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* sub = app.add_subcommand("render", "Render one frame of a showroom scene to EXR (+ tone-mapped PNG)");
  sub->add_option("--scene", a->scene, "Scene: a name (assets/scenes/NAME.json: swatch, pillow, drape, teapot, curtain) or a path to a .json scene or a .gltf/.glb file")
      ->capture_default_str();
  sub->add_option("--fabric", a->fabric, "Fabric (preset name or .json file) for every cloth object (default: the scene's; a glTF naming no cloth: every material)");
  sub->add_option("--map,--env", a->env, "Environment map: a name (assets/envmaps/NAME.exr) or an .exr path, NAME@DEG (rotated about +Z), or "
                  "sky:elev=E,size=S,haze=T,azim=A,albedo=G (procedural) (default: the scene's)");
  sub->add_option("--method", a->method, "Method: reference (ground truth of docs/design.md §2, CPU) or a GPU method: sgpoint, iwasaki, iwasaki_vertex, mizutani, sheen, mdfrot, thin (mizutani bakes its tables first)")->capture_default_str();
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
  sub->add_option("--bundle", a->bundle, "iwasaki, iwasaki_vertex, mizutani: take the scene and weighting tables from this bundle (weft bake) instead of baking them");
  sub->add_option("--table-grid", a->table_grid, "Methods reading weighting tables, without --bundle: direction grids of the tables baked in memory, N x N (default: the paper's 48; smaller bakes faster, as weft bake --table-grid)")->check(CLI::Range(4, 128));
  sub->add_option("--frames", a->timed_frames, "GPU methods: frames timed after a warm-up (median reported)")
      ->capture_default_str();
  sub->add_option("--exposure", a->exposure, "PNG: fixed exposure before the filmic curve and sRGB (0: metered on the cloth)")
      ->capture_default_str();
  sub->add_option("--exposure-bias", a->exposure_bias, "PNG: EV added to the metered exposure (+1: twice as bright)")->capture_default_str();
  sub->add_flag("--weave", a->weave, "The resolved weave: up close each point shows the thread that lies there (GPU methods: the weave layer over the method; reference: the resolved model, supersampled)");
  sub->add_option("--weave-terms", a->weave_terms, "GPU methods shading per vertex, with --weave: each float lit per pixel over the method's level (pixel) or from a per-vertex table (table: the kiosk's choice on a GPU too slow for pixel)")->check(CLI::IsMember({"pixel", "table"}))->capture_default_str();
  sub->add_option("--supersample", a->supersample, "Reference: rays per pixel along each axis (default 4 with --weave, else 1)");
  sub->add_option("--camera", a->camera, "scene: the scene's camera; closeup: its close-up camera (or the camera moved in until a weave repeat spans 24 pixels); EX,EY,EZ:TX,TY,TZ[:FOV]: eye and target in the scene's metres, the scene camera's up, FOV its vertical field of view (degrees)")->capture_default_str();
  sub->add_option("--backdrop", a->backdrop, "GPU methods: showroom (the environment, softened, behind the scene) or measure (black; the sharp environment behind see-through cloth, as the bench draws)")->capture_default_str();
  return [a] { return run_render(*a); };
}

}  // namespace weft
