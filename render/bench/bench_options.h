#pragma once
// What `weft bench` measures, as its flags set it (defaults are the flags' defaults), the
// settings --quick puts in place, the checks of the ranges, and the command that regenerates a run.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace weft::bench {

// A setting out of range or naming nothing (an unknown scene, method or map): bad input, exit 2.
class InvalidOption : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The most tangent samples per thread a converging reference takes.
inline constexpr int kReferenceTangentCap = 256;

struct BenchOptions {
  bool quick = false;
  std::string sweep;  // a preset of scenes, maps and methods (sky_sweep.h): "sky", "sky-smoke"
  std::string out = "bench-out";
  std::string cache;  // default: <out>/reference-cache
  std::filesystem::path assets;  // scenes/, fabrics/, envmaps/
  std::vector<std::string> scenes{"swatch", "pillow", "drape", "teapot", "curtain"};
  std::vector<std::string> fabrics{"scene"};
  std::vector<std::string> envs{"scene"};
  std::vector<std::string> methods;  // empty: all available
  int speed_width = 640, speed_height = 480, speed_frames = 20;
  int width = 320, height = 240;
  // Reference: SG grid; tangent samples per thread N_j, the minimum the reference starts from
  // (reference_set.h: doubled up to kReferenceTangentCap until the cloth changes by at most
  // reference_tolerance; 0: fixed at tangent_samples).
  int sg_grid = 8, tangent_samples = 32, sg_count = 10;
  double reference_tolerance = 0.01;
  int stress_points = 24;
  bool no_stability = false;
  bool no_sweeps = false;      // none of the cost-knob sweeps below, --quick's own included
  int bake_grid = 0;           // iwasaki tables' ξ/ω grids n×n; 0: the paper's 48 (12 with --quick)
  double target_error = 0.05;  // > 0: `iwasaki (target E)`, `iwasaki_vertex (target E)` rows (bake/selection/scene_selection.h)
  // Midpoint subdivision levels > 0 (scene/mesh_subdivision.h): each per-vertex method row is
  // followed by a row drawn on the cloth meshes refined that many levels, with the visibility
  // baked on them (`METHOD (subdivision L)`), against the same reference.
  std::vector<int> subdivide;
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

// With `quick`: the smoke run's scene, sizes and sweeps in place of the defaults.
void apply_quick(BenchOptions& o);
// Throws InvalidOption naming the flag whose value is out of range.
void validate(const BenchOptions& o);
// The command that regenerates this run, every setting spelled out.
std::string command_line(const BenchOptions& o);

}  // namespace weft::bench
