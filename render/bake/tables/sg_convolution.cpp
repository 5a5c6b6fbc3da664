#include "bake/tables/sg_convolution.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <omp.h>

namespace weft {

WeightGrid evaluate_weight_grid(const ClothBsdf& bsdf, int wi_n, std::span<const glm::dvec3> wo,
                                const std::function<void(int, int)>& progress) {
  WeightGrid g;
  g.wi.n = wi_n;
  g.wo_count = static_cast<int>(wo.size());
  const int samples = bsdf.total_samples();
  const int wi_count = g.wi.size();
  g.w.assign(samples, std::vector<float>(size_t(wi_count) * wo.size()));
  std::vector<glm::dvec3> wi(wi_count);
  for (int i = 0; i < wi_count; ++i) wi[i] = g.wi.node(i);

  std::atomic<int> done{0};
#pragma omp parallel
  {
    ClothBsdf::Point point = bsdf.at(SurfaceFrame{});
    std::vector<double> weights(samples);
#pragma omp for schedule(dynamic, 4)
    for (int o = 0; o < g.wo_count; ++o) {
      for (int i = 0; i < wi_count; ++i) {
        point.weights(wi[i], wo[o], weights);
        for (int t = 0; t < samples; ++t) g.w[t][size_t(o) * wi_count + i] = static_cast<float>(weights[t]);
      }
      const int d = ++done;
      if (progress && omp_get_thread_num() == 0) progress(d, g.wo_count);
    }
  }
  if (progress) progress(g.wo_count, g.wo_count);
  return g;
}

SgKernel sg_kernel(const HemisphereNodeGrid& grid, std::span<const glm::dvec3> xi, double lambda, int quadrature_n) {
  const HemisphereCellGrid quad{quadrature_n > 0 ? quadrature_n : grid.n};
  SgKernel k;
  k.rows = static_cast<int>(xi.size());
  k.cols = grid.size();
  k.g.assign(size_t(k.rows) * k.cols, 0.0f);
  std::vector<glm::dvec3> wq(quad.size());
  for (int i = 0; i < quad.size(); ++i) wq[i] = quad.centre(i);
  // Bilinear taps of each quadrature cell centre among the ω_i nodes, through the node grid's own
  // square (not the cells': the two squares differ, hemisphere_grid.h).
  std::vector<BilinearTap> taps(quad.size());
  for (int c = 0; c < quad.size(); ++c) taps[c] = grid.tap(wq[c]);
#pragma omp parallel
  {
    std::vector<double> row(k.cols);
#pragma omp for schedule(dynamic, 8)
    for (int r = 0; r < k.rows; ++r) {
      std::fill(row.begin(), row.end(), 0.0);
      double sum = 0.0;
      for (int c = 0; c < quad.size(); ++c) {
        const double g = std::exp(lambda * (glm::dot(xi[r], wq[c]) - 1.0));
        if (g < 1e-12) continue;  // beyond the lobe's reach: below float resolution of the row
        sum += g;
        for (int q = 0; q < 4; ++q) row[taps[c].index[q]] += g * taps[c].weight[q];
      }
      const double inv = sum > 0.0 ? 1.0 / sum : 0.0;
      for (int i = 0; i < k.cols; ++i) k.g[size_t(i) * k.rows + r] = static_cast<float>(row[i] * inv);
    }
  }
  return k;
}

std::vector<float> convolve_weights(const WeightGrid& grid, int t, const SgKernel& kernel) {
  const int wi_count = grid.wi.size();
  if (kernel.cols != wi_count) throw std::invalid_argument("convolve_weights: kernel and grid disagree on ω_i");
  const Eigen::Map<const Eigen::MatrixXf> g(kernel.g.data(), kernel.rows, kernel.cols);
  const Eigen::Map<const Eigen::MatrixXf> w(grid.w[t].data(), wi_count, grid.wo_count);
  std::vector<float> out(size_t(kernel.rows) * grid.wo_count);
  Eigen::Map<Eigen::MatrixXf> result(out.data(), kernel.rows, grid.wo_count);
  result.noalias() = g * w;
  return out;
}

std::vector<float> convolve_all_weights(const WeightGrid& grid, const SgKernel& kernel, std::span<const int> samples) {
  const int wi_count = grid.wi.size();
  if (kernel.cols != wi_count) throw std::invalid_argument("convolve_all_weights: kernel and grid disagree on ω_i");
  const Eigen::Map<const Eigen::MatrixXf> g(kernel.g.data(), kernel.rows, kernel.cols);
  // Stack the samples' W side by side so one large GEMM does every sample.
  std::vector<int> all;
  if (samples.empty()) {
    for (int t = 0; t < grid.samples(); ++t) all.push_back(t);
    samples = all;
  }
  Eigen::MatrixXf w(wi_count, size_t(grid.wo_count) * samples.size());
  for (size_t k = 0; k < samples.size(); ++k)
    w.middleCols(k * grid.wo_count, grid.wo_count) =
        Eigen::Map<const Eigen::MatrixXf>(grid.w.at(samples[k]).data(), wi_count, grid.wo_count);
  std::vector<float> out(size_t(kernel.rows) * w.cols());
  Eigen::Map<Eigen::MatrixXf> result(out.data(), kernel.rows, w.cols());
  result.noalias() = g * w;
  return out;
}

}  // namespace weft
