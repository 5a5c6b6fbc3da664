#include "bake/sg_convolution.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <omp.h>

namespace weft {

WeightGrid WeightGrid::coarsened() const {
  if (wi.n % 2 != 0) throw std::invalid_argument("WeightGrid::coarsened: odd grid " + std::to_string(wi.n));
  WeightGrid c;
  c.wi.n = wi.n / 2;
  c.wo_count = wo_count;
  const int n = wi.n, m = c.wi.n;
  c.w.resize(w.size());
  for (size_t t = 0; t < w.size(); ++t) {
    c.w[t].assign(size_t(m) * m * wo_count, 0.0f);
    for (int o = 0; o < wo_count; ++o) {
      const float* src = w[t].data() + size_t(o) * n * n;
      float* dst = c.w[t].data() + size_t(o) * m * m;
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
          const int f = 2 * j * n + 2 * i;
          dst[j * m + i] = 0.25f * (src[f] + src[f + 1] + src[f + n] + src[f + n + 1]);
        }
    }
  }
  return c;
}

WeightGrid evaluate_weight_grid(const ClothBsdf& bsdf, int wi_n, std::span<const glm::dvec3> wo,
                                const std::function<void(int, int)>& progress) {
  WeightGrid g;
  g.wi.n = wi_n;
  g.wo_count = static_cast<int>(wo.size());
  const int samples = bsdf.total_samples();
  const int wi_count = g.wi.size();
  g.w.assign(samples, std::vector<float>(size_t(wi_count) * wo.size()));
  std::vector<glm::dvec3> wi(wi_count);
  for (int i = 0; i < wi_count; ++i) wi[i] = g.wi.centre(i);

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

SgKernel sg_kernel(const HemisphereCellGrid& grid, std::span<const glm::dvec3> xi, double lambda) {
  SgKernel k;
  k.rows = static_cast<int>(xi.size());
  k.cols = grid.size();
  k.g.resize(size_t(k.rows) * k.cols);
  std::vector<glm::dvec3> wi(k.cols);
  for (int i = 0; i < k.cols; ++i) wi[i] = grid.centre(i);
#pragma omp parallel for
  for (int r = 0; r < k.rows; ++r) {
    double sum = 0.0;
    for (int i = 0; i < k.cols; ++i) sum += std::exp(lambda * (glm::dot(xi[r], wi[i]) - 1.0));
    const double inv = sum > 0.0 ? 1.0 / sum : 0.0;
    for (int i = 0; i < k.cols; ++i)
      k.g[size_t(i) * k.rows + r] = float(std::exp(lambda * (glm::dot(xi[r], wi[i]) - 1.0)) * inv);
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

}  // namespace weft
