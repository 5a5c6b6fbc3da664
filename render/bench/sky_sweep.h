#pragma once
// `weft bench --sweep sky`: accuracy under lighting the project was not tuned for — procedural
// skies with the sun from the horizon to 60° (and larger, hazier suns), and the bundled maps
// turned about +Z — on the pillow and the drape in linen and satin, iwasaki and iwasaki_vertex
// against the reference under the same SGs. Next to the ladder's outputs it writes low_sun.csv:
// per case the two methods' errors, and per environment the SG fit's irradiance error with the
// bench's fit and with the light probe's warm-started update (and that update's time).
// `--sweep sky-smoke` is the same at a smoke test's size (one scene, one fabric, three
// environments, 64×48).
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_options.h"
#include "bench/bench_results.h"

namespace weft::bench {

// The environments of the full sweep and of its smoke version.
std::vector<std::string> sky_sweep_envs(bool smoke);

// Puts the sweep's scenes, fabrics, environments, methods and sizes in place when
// o.sweep is "sky" or "sky-smoke"; throws InvalidOption for any other non-empty value.
void apply_sweep(BenchOptions& o);

// The SG fit on one environment: the bench's fit (its irradiance error) and the probe's update
// (grid 64, 8 LM iterations, warm-started from the previous fit of the same map).
struct FitCondition {
  std::string env;
  double irradiance_error = 0.0;        // the bench's fit
  double probe_irradiance_error = 0.0;  // the probe's warm update
  double probe_update_ms = 0.0;         // median of 3 warm updates, this thread's CPU time
};
FitCondition measure_fit_condition(const BenchOptions& o, const std::string& env);

// low_sun.csv and low_sun.md under `out` (nothing when o.sweep is empty).
void write_sky_sweep(const std::filesystem::path& out, const BenchOptions& o, const BenchResults& res);

}  // namespace weft::bench
