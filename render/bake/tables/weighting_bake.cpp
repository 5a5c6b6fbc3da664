#include "bake/tables/weighting_bake.h"

#include <chrono>
#include <cmath>
#include <algorithm>
#include <stdexcept>

#include "bake/tables/low_rank.h"
#include "bake/tables/sg_convolution.h"
#include "core/cloth_bsdf.h"

namespace weft {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("bake settings: " + what);
}
}  // namespace

std::vector<double> BakeSettings::lambdas() const {
  std::vector<double> out(lambda_levels);
  for (int l = 0; l < lambda_levels; ++l) {
    const double f = lambda_levels > 1 ? double(l) / (lambda_levels - 1) : 0.0;
    out[l] = lambda_min * std::pow(lambda_max / lambda_min, f);
  }
  return out;
}

void BakeSettings::validate() const {
  for (int j = 0; j < 2; ++j)
    require(tangent_samples[j] >= 1 && tangent_samples[j] <= 256,
            "tangent_samples[" + std::to_string(j) + "] must be in [1, 256], got " + std::to_string(tangent_samples[j]));
  require(xi_resolution >= 2 && xi_resolution <= 512, "xi_resolution must be in [2, 512]");
  require(wo_resolution >= 2 && wo_resolution <= 512, "wo_resolution must be in [2, 512]");
  require(wi_resolution >= 2 && wi_resolution <= 1024, "wi_resolution must be in [2, 1024]");
  require(cell_per_lobe > 0.0 && std::isfinite(cell_per_lobe), "cell_per_lobe must be positive");
  require(lambda_min > 0.0 && std::isfinite(lambda_min) && lambda_max >= lambda_min && std::isfinite(lambda_max) &&
              lambda_max <= 1e5,
          "need 0 < lambda_min <= lambda_max <= 1e5");
  require(lambda_levels >= 1 && lambda_levels <= 64, "lambda_levels must be in [1, 64]");
  require(lambda_levels == 1 || lambda_max > lambda_min, "several lambda levels need lambda_max > lambda_min");
  require(svd_error > 0.0 && svd_error < 1.0, "svd_error must be in (0, 1)");
  require(max_rank >= 0, "max_rank must be >= 0");
}

int quadrature_resolution_for(const BakeSettings& s, double lambda) {
  const int needed = static_cast<int>(std::ceil(std::sqrt(2.0 * 3.141592653589793 * lambda) / s.cell_per_lobe));
  return std::clamp(needed, s.wi_resolution, 1024);
}

WeightingTables bake_weighting_tables(const Fabric& fabric, const BakeSettings& settings, const BakeProgress& progress,
                                      BakeTimings* timings) {
  settings.validate();
  BakeTimings local;
  BakeTimings& time = timings ? *timings : local;
  time = {};
  auto report = [&](double f, std::string_view stage) {
    if (progress) progress(f, stage);
  };

  WeightingTables out;
  out.tangent_samples = settings.tangent_samples;
  out.xi_grid.n = settings.xi_resolution;
  out.wo_grid.n = settings.wo_resolution;
  out.lambdas = settings.lambdas();
  const ClothBsdf bsdf(fabric, settings.tangent_samples);
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < bsdf.sample_count(j); ++k) out.tilts.push_back(bsdf.tilt(j, k));
  const int levels = out.level_count();

  std::vector<glm::dvec3> xi(out.xi_grid.size()), wo(out.wo_grid.size());
  for (int i = 0; i < out.xi_grid.size(); ++i) xi[i] = out.xi_grid.node(i);
  for (int i = 0; i < out.wo_grid.size(); ++i) wo[i] = out.wo_grid.node(i);

  // Share of the progress bar: W grid first, then one step per (level, t).
  constexpr double kWeightShare = 0.3;
  auto t0 = std::chrono::steady_clock::now();
  const WeightGrid grid = evaluate_weight_grid(bsdf, settings.wi_resolution, wo, [&](int done, int total) {
    report(kWeightShare * done / total, "weights W(t, ω_i, ω_o)");
  });
  time.weights_s = seconds_since(t0);

  // One table per distinct (thread, tilt).
  std::vector<int> distinct;  // first sample of each distinct table
  for (int j = 0, t = 0; j < 2; ++j)
    for (int k = 0; k < bsdf.sample_count(j); ++k, ++t) {
      int d = 0;
      while (d < int(distinct.size()) && !(out.tilts[distinct[d]] == out.tilts[t] && (distinct[d] < bsdf.sample_count(0)) == (j == 0)))
        ++d;
      if (d == int(distinct.size())) distinct.push_back(t);
      out.sample_table.push_back(d);
    }
  const int tables = static_cast<int>(distinct.size());
  out.tables.resize(size_t(tables) * levels);
  LowRankOptions lr;
  lr.relative_error = settings.svd_error;
  lr.max_rank = settings.max_rank;
  const size_t block = size_t(xi.size()) * grid.wo_count;
  for (int l = 0; l < levels; ++l) {
    const double lambda = out.lambdas[l];
    auto tc = std::chrono::steady_clock::now();
    const SgKernel kernel = sg_kernel(grid.wi, xi, lambda, quadrature_resolution_for(settings, lambda));
    const std::vector<float> all = convolve_all_weights(grid, kernel, distinct);
    time.convolve_s += seconds_since(tc);
    // The samples' SVDs are independent: one per thread of execution (Eigen then runs each
    // single-threaded, which suits these thin products better than splitting each one).
    tc = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 1)
    for (int d = 0; d < tables; ++d) {
      LowRankOptions opt = lr;
      opt.seed = 1u + unsigned(d * levels + l);
      LowRankFactors f = truncated_svd(all.data() + d * block, kernel.rows, grid.wo_count, opt);
      CompressedTable& c = out.tables[size_t(d) * levels + l];
      c.rank = f.rank;
      c.u = std::move(f.u);
      c.v = std::move(f.v);
      c.norm = f.norm;
      c.error = f.error;
    }
    time.compress_s += seconds_since(tc);
    report(kWeightShare + (1.0 - kWeightShare) * double(l + 1) / levels, "convolve + compress T_{t,λ}");
  }
  return out;
}

}  // namespace weft
