#pragma once
// The bench's outputs: results.csv (one line per row), chart.png (speed against accuracy),
// report.md (the tables and images of the whole run), and the sweeps' CSVs.
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_options.h"
#include "bench/bench_results.h"
#include "bench/chart.h"

namespace weft::bench {

// How the references' tangent samples were set, in words (report.md, low_sun.md).
std::string reference_samples_text(const BenchOptions& o);

void write_results_csv(const std::filesystem::path& out, const BenchOptions& o, const BenchResults& res);
void write_chart(const std::filesystem::path& out, const BenchOptions& o, const BenchResults& res);
void write_report_md(const std::filesystem::path& out, const BenchOptions& o, const BenchResults& res);
void write_sg_sweep_csv(const std::filesystem::path& file, const std::vector<SweepRow>& sweep);
void write_knob_sweep_csv(const std::filesystem::path& file, const KnobSweep& ks);

}  // namespace weft::bench
