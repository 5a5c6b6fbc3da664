#pragma once
// The cost-knob sweeps on the first scene: the SG count (K SGs fitted to the scene's map,
// against the reference lit by the map itself), and iwasaki's bake knobs one at a time from the
// paper-default bundle (tangent samples, SVD error, SDF resolution and supersampling), each
// written to its CSV as soon as it is measured.
#include <filesystem>
#include <vector>

#include "bench/bench_options.h"
#include "bench/bench_results.h"
#include "bench/ladder.h"
#include "bench/reference_set.h"
#include "bench/table_bakes.h"

namespace weft::bench {

// Fills results.sweep and results.sweep_case; writes sweep_sg_count.csv. Nothing without
// --sweep-sg-counts.
void sweep_sg_counts(const BenchOptions& o, const std::vector<LadderEntry>& run, TableBakes& bakes,
                     ReferenceSet& references, const std::filesystem::path& out, BenchResults& results);

// Fills results.knob_sweeps, knob_case and knob_default; writes sweep_<knob>.csv per swept
// knob. Nothing without a --sweep-<knob> flag.
void sweep_bake_knobs(const BenchOptions& o, bool has_iwasaki, TableBakes& bakes, ReferenceSet& references,
                      const std::filesystem::path& out, BenchResults& results);

}  // namespace weft::bench
