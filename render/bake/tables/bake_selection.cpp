#include "bake/tables/bake_selection.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#include <Eigen/Dense>

#include "bake/tables/sg_convolution.h"
#include "core/cloth_bsdf.h"

namespace weft {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Probe radiance L(ξ, ω_o), (ξ × ω_o) column-major.
Eigen::MatrixXd probe_radiance(const Fabric& fabric, std::array<int, 2> samples, const TangentProbe& p) {
  const ClothBsdf bsdf(fabric, samples);
  const HemisphereNodeGrid wi_grid{p.wi_resolution};
  const HemisphereCellGrid wo_grid{p.wo_resolution};
  const HemisphereNodeGrid xi_grid{p.xi_resolution};
  std::vector<glm::dvec3> wi(wi_grid.size()), xi(xi_grid.size());
  for (int i = 0; i < wi_grid.size(); ++i) wi[i] = wi_grid.node(i);
  for (int i = 0; i < xi_grid.size(); ++i) xi[i] = xi_grid.node(i);
  Eigen::MatrixXd f(wi_grid.size(), wo_grid.size());
#pragma omp parallel
  {
    ClothBsdf::Point point = bsdf.at(SurfaceFrame{});
#pragma omp for schedule(dynamic, 2)
    for (int o = 0; o < wo_grid.size(); ++o) {
      const glm::dvec3 wo = wo_grid.centre(o);
      for (int i = 0; i < wi_grid.size(); ++i) {
        const glm::dvec3 v = point.integrand(wi[i], wo);
        f(i, o) = v.r + v.g + v.b;
      }
    }
  }
  BakeSettings quadrature;
  quadrature.wi_resolution = p.wi_resolution;
  const SgKernel k = sg_kernel(wi_grid, xi, p.lambda, quadrature_resolution_for(quadrature, p.lambda));
  const Eigen::Map<const Eigen::MatrixXf> g(k.g.data(), k.rows, k.cols);
  return g.cast<double>() * f;
}

double relative_rms(const Eigen::MatrixXd& x, const Eigen::MatrixXd& ref) {
  const double mean = ref.mean();
  if (!(mean > 0.0)) return (x - ref).norm() == 0.0 ? 0.0 : INFINITY;
  return std::sqrt((x - ref).squaredNorm() / ref.size()) / mean;
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}
}  // namespace

double tangent_sample_error(const Fabric& fabric, std::array<int, 2> samples, std::array<int, 2> reference,
                            const TangentProbe& probe) {
  return relative_rms(probe_radiance(fabric, samples, probe), probe_radiance(fabric, reference, probe));
}

namespace {
Choice select_tangent_samples_against(const Fabric& fabric, int thread, double target, const TangentProbe& probe,
                                      const Eigen::MatrixXd& ref) {
  const int nc = probe.converged_samples;
  Choice c;
  for (int n : probe.candidates) {
    std::array<int, 2> s{nc, nc};
    s[thread] = n;
    const double e = relative_rms(probe_radiance(fabric, s, probe), ref);
    c.tried.emplace_back(n, e);
    c.value = n;
    c.error = e;
    if (e <= target) break;
  }
  return c;
}
}  // namespace

Choice select_tangent_samples(const Fabric& fabric, int thread, double target, const TangentProbe& probe) {
  const int nc = probe.converged_samples;
  return select_tangent_samples_against(fabric, thread, target, probe, probe_radiance(fabric, {nc, nc}, probe));
}

Choice select_lambda_levels(const Fabric& fabric, const BakeSettings& base, double target, int xi_stride,
                            int wo_stride) {
  base.validate();
  constexpr int kLadder = 33;  // ×2^{1/4}: the candidates' levels and their midpoints
  BakeSettings ladder = base;
  ladder.lambda_levels = kLadder;
  const std::vector<double> lambdas = ladder.lambdas();

  const HemisphereNodeGrid xi_grid{base.xi_resolution}, wo_grid{base.wo_resolution};
  std::vector<glm::dvec3> xi, wo;
  for (int j = 0; j < xi_grid.n; j += xi_stride)
    for (int i = 0; i < xi_grid.n; i += xi_stride) xi.push_back(xi_grid.node(j * xi_grid.n + i));
  for (int j = 0; j < wo_grid.n; j += wo_stride)
    for (int i = 0; i < wo_grid.n; i += wo_stride) wo.push_back(wo_grid.node(j * wo_grid.n + i));

  const ClothBsdf bsdf(fabric, base.tangent_samples);
  const WeightGrid grid = evaluate_weight_grid(bsdf, base.wi_resolution, wo);
  // T on the ladder: [level][t], each (ξ subsample × ω_o).
  std::vector<std::vector<Eigen::MatrixXf>> t_at(kLadder);
  for (int l = 0; l < kLadder; ++l) {
    const SgKernel k = sg_kernel(grid.wi, xi, lambdas[l], quadrature_resolution_for(base, lambdas[l]));
    const std::vector<float> all = convolve_all_weights(grid, k);
    for (int t = 0; t < grid.samples(); ++t)
      t_at[l].push_back(Eigen::Map<const Eigen::MatrixXf>(all.data() + size_t(t) * k.rows * grid.wo_count, k.rows,
                                                         grid.wo_count));
  }
  Choice c;
  for (int stride : {8, 4, 2}) {
    double err2 = 0.0, norm2 = 0.0;
    for (int lo = 0; lo + stride < kLadder; lo += stride)
      for (size_t t = 0; t < t_at[lo].size(); ++t) {
        // Midpoint in log λ: the runtime's interpolation weight is ½.
        const Eigen::MatrixXf interp = 0.5f * (t_at[lo][t] + t_at[lo + stride][t]);
        const Eigen::MatrixXf& mid = t_at[lo + stride / 2][t];
        err2 += (interp - mid).cast<double>().squaredNorm();
        norm2 += mid.cast<double>().squaredNorm();
      }
    const double e = norm2 > 0.0 ? std::sqrt(err2 / norm2) : 0.0;
    const int levels = (kLadder - 1) / stride + 1;
    c.tried.emplace_back(levels, e);
    c.value = levels;
    c.error = e;
    if (e <= target) break;
  }
  return c;
}

SelectionResult select_bake_settings(const Fabric& fabric, double target, const BakeSettings& base,
                                     const BakeProgress& progress) {
  SelectionResult r;
  r.settings = base;
  auto report = [&](double f, std::string_view s) {
    if (progress) progress(f, s);
  };
  const char* thread_names[2] = {"tangent samples, thread 1", "tangent samples, thread 2"};
  const TangentProbe probe;
  auto t_ref = std::chrono::steady_clock::now();
  report(0.0, "converged reference for tangent samples");
  const Eigen::MatrixXd ref =
      probe_radiance(fabric, {probe.converged_samples, probe.converged_samples}, probe);
  r.rows.push_back({"tangent-sample reference", std::to_string(probe.converged_samples) + "+" +
                                                    std::to_string(probe.converged_samples) + " (converged)",
                    0.0, 0, seconds_since(t_ref)});
  for (int j = 0; j < 2; ++j) {
    report(0.2 + 0.3 * j, thread_names[j]);
    auto t0 = std::chrono::steady_clock::now();
    const Choice c = select_tangent_samples_against(fabric, j, target, probe, ref);
    r.settings.tangent_samples[j] = c.value;
    r.rows.push_back({thread_names[j], std::to_string(c.value), c.error, 0, seconds_since(t0)});
  }
  report(0.8, "λ levels");
  const auto t0 = std::chrono::steady_clock::now();
  const Choice levels = select_lambda_levels(fabric, r.settings, target);
  r.settings.lambda_levels = levels.value;
  r.rows.push_back({"λ levels", std::to_string(levels.value) + " over " + fixed(base.lambda_min, 4) + ".." +
                                    fixed(base.lambda_max, 5),
                    levels.error, 0, seconds_since(t0)});
  r.settings.svd_error = target;
  report(1.0, "settings chosen");
  return r;
}

}  // namespace weft
