#pragma once
// `weft bench`: the speed/accuracy ladder. Every GPU method × scene × fabric × environment:
// speed at 640×480 (median over ≥ 20 frames after a warm-up, glFinish included) and accuracy
// at 320×240 as relative RMSE over the cloth pixels against a cached `reference` render under
// the same SGs; the `weft bake --target-error` point of iwasaki next to its paper-default row;
// sweeps of iwasaki's cost knobs (SG count, tangent samples, SVD error, SDF resolution) on the
// first scene; then the stability table (stability.h) and, from the teapot images, the
// thin-occluder table (errors inside the sun's shadow). Writes results.csv, sweep_*.csv,
// chart.png, report.md and the images the report shows into --out, and one JSON line on stdout.
#include "bench/bench_options.h"

namespace weft::bench {

// Applies --quick, checks the options (InvalidOption), runs every step; returns the exit code.
int run_bench(BenchOptions o);

}  // namespace weft::bench
