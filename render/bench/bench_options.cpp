#include "bench/bench_options.h"

#include <sstream>

#include "bench/number_text.h"

namespace weft::bench {

namespace {

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

}  // namespace

void apply_quick(BenchOptions& a) {
  if (!a.quick) return;
  a.scenes = {"swatch"};
  a.fabrics = {"linen_plain"};
  a.envs = {"scene"};
  a.speed_width = 64, a.speed_height = 48;  // --speed-frames stays (20 by default)
  a.width = 64, a.height = 48;
  a.sg_grid = 4, a.tangent_samples = 8, a.reference_tolerance = 0.0;  // a smoke run: N_j fixed
  a.stress_points = 2;
  a.bake_grid = 12;
  // Smoke versions of iwasaki's knob sweeps (grid-12 tables: seconds each). No SDF sweep:
  // swatch has no occluded cloth.
  if (!a.no_sweeps && a.sweep_tangent_samples.empty()) a.sweep_tangent_samples = {1, 3};
  if (!a.no_sweeps && a.sweep_svd_errors.empty()) a.sweep_svd_errors = {0.1, 0.01};
}

void validate(const BenchOptions& a) {
  if (a.no_sweeps && !(a.sweep_sg_counts.empty() && a.sweep_tangent_samples.empty() && a.sweep_svd_errors.empty() &&
                       a.sweep_sdf_resolutions.empty() && a.sweep_sdf_supersamples.empty()))
    throw InvalidOption("--no-sweeps: leaves no sweep to run, but a --sweep-<knob> flag asks for one");
  if (a.speed_frames < 1 || a.speed_frames > 1000) throw InvalidOption("--speed-frames: must be within 1..1000");
  if (a.width < 8 || a.height < 8 || a.width > 4096 || a.height > 4096 || a.speed_width < 8 || a.speed_height < 8 ||
      a.speed_width > 4096 || a.speed_height > 4096)
    throw InvalidOption("--width/--height/--speed-width/--speed-height: must be within 8..4096");
  if (a.sg_grid < 1 || a.sg_grid > 256) throw InvalidOption("--sg-grid: must be within 1..256");
  if (a.tangent_samples < 1 || a.tangent_samples > 64) throw InvalidOption("--tangent-samples: must be within 1..64");
  if (!(a.reference_tolerance >= 0.0 && a.reference_tolerance < 1.0))
    throw InvalidOption("--reference-tolerance: must be within [0, 1)");
  if (a.sg_count < 1 || a.sg_count > 40) throw InvalidOption("--sg-count: must be within 1..40");
  if (a.stress_points < 0 || a.stress_points > 1000) throw InvalidOption("--stress-points: must be within 0..1000");
  if (a.bake_grid != 0 && (a.bake_grid < 4 || a.bake_grid > 96)) throw InvalidOption("--table-grid: must be 0 or within 4..96");
  if (!(a.target_error >= 0.0 && a.target_error < 1.0)) throw InvalidOption("--target-error: must be within [0, 1)");
  for (int k : a.sweep_sg_counts)
    if (k < 1 || k > 40) throw InvalidOption("--sweep-sg-counts: each must be within 1..40");
  for (int k : a.sweep_tangent_samples)
    if (k < 1 || k > 32) throw InvalidOption("--sweep-tangent-samples: each must be within 1..32");
  for (double e : a.sweep_svd_errors)
    if (!(e > 0.0 && e < 1.0)) throw InvalidOption("--sweep-svd-error: each must be within (0, 1)");
  for (int r : a.sweep_sdf_resolutions)
    if (r < 4 || r > 128) throw InvalidOption("--sweep-sdf-resolution: each must be within 4..128");
  for (int r : a.sweep_sdf_supersamples)
    if (r < 1 || r > 4) throw InvalidOption("--sweep-sdf-supersample: each must be within 1..4");
  for (int l : a.subdivide)
    if (l < 1 || l > 3) throw InvalidOption("--subdivide: each level must be within 1..3");
}

std::string command_line(const BenchOptions& a) {
  std::ostringstream c;
  c << "weft bench";
  if (!a.sweep.empty()) c << " --sweep " << a.sweep;
  if (a.quick) c << " --quick";
  else
    c << " --scenes " << joined(a.scenes) << " --fabrics " << joined(a.fabrics) << " --maps " << joined(a.envs)
      << " --speed-width " << a.speed_width << " --speed-height " << a.speed_height << " --width " << a.width
      << " --height " << a.height << " --sg-grid " << a.sg_grid << " --tangent-samples " << a.tangent_samples
      << " --reference-tolerance " << fmt(a.reference_tolerance, 4) << " --stress-points " << a.stress_points;
  c << " --speed-frames " << a.speed_frames << " --sg-count " << a.sg_count;
  if (!a.methods.empty()) c << " --methods " << joined(a.methods);
  if (a.no_stability) c << " --no-stability";
  if (a.no_sweeps) c << " --no-sweeps";
  if (!a.quick && a.bake_grid > 0) c << " --table-grid " << a.bake_grid;
  c << " --target-error " << fmt(a.target_error, 4);
  if (!a.subdivide.empty()) c << " --subdivide " << joined_numbers(a.subdivide);
  if (!a.sweep_sg_counts.empty()) c << " --sweep-sg-counts " << joined_numbers(a.sweep_sg_counts);
  if (!a.sweep_tangent_samples.empty()) c << " --sweep-tangent-samples " << joined_numbers(a.sweep_tangent_samples);
  if (!a.sweep_svd_errors.empty()) c << " --sweep-svd-error " << joined_numbers(a.sweep_svd_errors);
  if (!a.sweep_sdf_resolutions.empty()) c << " --sweep-sdf-resolution " << joined_numbers(a.sweep_sdf_resolutions);
  if (!a.sweep_sdf_supersamples.empty()) c << " --sweep-sdf-supersample " << joined_numbers(a.sweep_sdf_supersamples);
  c << " --out " << a.out;
  return c.str();
}

}  // namespace weft::bench
