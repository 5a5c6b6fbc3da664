// Measurements for the visibility bake (label `bench`, not run in CI): EDT/SDF timings at the
// paper's 128² resolution, PCA terms against error on an Embree scene, κ table fit time and
// error. Prints numbers; asserts nothing about speed.
#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>

#include "bake/visibility/sigmoid_gain.h"
#include "bake/visibility/visibility_pca.h"
#include "bake/visibility/visibility_sdf.h"

using namespace weft;

namespace {

constexpr double kPi = std::numbers::pi;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Ground plane plus random axis-aligned boxes: a cluttered shelf for the vertices on the plane.
class BoxScene {
 public:
  explicit BoxScene(unsigned seed) {
    device_ = rtcNewDevice(nullptr);
    scene_ = rtcNewScene(device_);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-2.f, 2.f), size(0.1f, 0.8f);
    for (int b = 0; b < 6; ++b) {
      const glm::vec3 lo(pos(rng), pos(rng), 0.f);
      add_box(lo, lo + glm::vec3(size(rng), size(rng), size(rng)));
    }
    rtcCommitScene(scene_);
  }
  ~BoxScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  bool occluded(const dvec3& o, const dvec3& d) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = float(o.x), ray.org_y = float(o.y), ray.org_z = float(o.z);
    ray.dir_x = float(d.x), ray.dir_y = float(d.y), ray.dir_z = float(d.z);
    ray.tfar = std::numeric_limits<float>::infinity();
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0;
  }

 private:
  void add_box(glm::vec3 lo, glm::vec3 hi) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), 8));
    for (int k = 0; k < 8; ++k) {
      v[3 * k] = k & 1 ? hi.x : lo.x;
      v[3 * k + 1] = k & 2 ? hi.y : lo.y;
      v[3 * k + 2] = k & 4 ? hi.z : lo.z;
    }
    const unsigned faces[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                                   {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), 12));
    for (int f = 0; f < 12; ++f)
      for (int c = 0; c < 3; ++c) idx[3 * f + c] = faces[f][c];
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
  }
  RTCDevice device_;
  RTCScene scene_;
};

}  // namespace

TEST(VisibilityBench, SignedDistanceAt128) {
  const int n = 128;
  std::mt19937 rng(1);
  VisibilityGrid v{n, 2 * n, std::vector<uint8_t>(2 * n * n)};
  std::uniform_real_distribution<double> u(-1, 1);
  const double a = u(rng), b = u(rng);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j)
      v.at(i, j) = std::abs(cell_centre(-kPi, kPi / n, j)) < kPi / 2 &&
                   std::sin(3 * cell_centre(-kPi / 2, kPi / n, i)) * a + b * std::cos(2 * cell_centre(-kPi, kPi / n, j)) < 0.3;
  const int reps = 200;
  auto t0 = Clock::now();
  double sink = 0;
  for (int r = 0; r < reps; ++r) sink += signed_distance(v, kPi / n, true, true).values[r];
  const double full = seconds_since(t0) / reps;
  const VisibilityGrid hemi = hemisphere_crop(v);
  t0 = Clock::now();
  for (int r = 0; r < reps; ++r) sink += signed_distance(hemi, kPi / n, false, true).values[r];
  const double square = seconds_since(t0) / reps;
  const DistanceGrid d = signed_distance(hemi, kPi / n, false, true);
  t0 = Clock::now();
  for (int r = 0; r < reps; ++r) sink += sdf_gradient(d, kPi / n, false).d_theta.values[r];
  const double grad = seconds_since(t0) / reps;
  std::printf("SDF (two exact EDTs) 128×256 periodic φ: %.3f ms; 128×128 square: %.3f ms; ∇d: %.3f ms  [%g]\n",
              full * 1e3, square * 1e3, grad * 1e3, sink * 0);
}

TEST(VisibilityBench, EmbreeSceneSdfsAndPcaTermsAgainstError) {
  const BoxScene scene(5);
  auto occluded = [&](const dvec3& o, const dvec3& d) { return scene.occluded(o, d); };
  const int resolution = 128;
  const int side = std::getenv("WEFT_BENCH_VERTICES_SIDE") ? std::atoi(std::getenv("WEFT_BENCH_VERTICES_SIDE")) : 20;
  Eigen::MatrixXf sdfs(resolution * resolution, side * side);
  auto t0 = Clock::now();
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < side * side; ++k) {
    const dvec3 p(-2.5 + 5.0 * (k % side + 0.5) / side, -2.5 + 5.0 * (k / side + 0.5) / side, 1e-4);
    const VertexSdf s = vertex_sdf(SurfaceFrame{}, p, resolution, 1, occluded);
    for (int c = 0; c < resolution * resolution; ++c) sdfs(c, k) = float(s.d.values[c]);
  }
  const double t_sdf = seconds_since(t0);
  std::printf("%d vertices, 128² hemisphere, 1 ray/cell: %.2f s (%.1f ms/vertex incl. %d rays)\n", side * side,
              t_sdf, 1e3 * t_sdf / (side * side), resolution * resolution);
  for (double target : {0.02, 0.01, 0.005}) {
    SdfPcaOptions opt;
    opt.target_rms_error = target;
    opt.max_terms = 96;
    t0 = Clock::now();
    const SdfPca pca = fit_sdf_pca(sdfs, opt);
    const double t_pca = seconds_since(t0);
    const double bytes = 4.0 * (pca.mean.size() + pca.basis.size() + pca.coefficients.size());
    std::printf("PCA target %.3f rad: %d terms, RMS %.4f rad, max %.3f rad, %.2f MB (float), %.2f s\n", target,
                pca.terms(), pca.rms_error, pca.max_error, bytes / 1e6, t_pca);
    if (target == 0.005) {
      std::printf("  RMS error by terms:");
      for (int k : {0, 1, 2, 4, 8, 16, 24, 32, 48, 64, 96})
        if (k < int(pca.rms_error_by_terms.size())) std::printf(" %d:%.4f", k, pca.rms_error_by_terms[k]);
      std::printf("\n");
    }
  }
}

TEST(VisibilityBench, GradientDirectionWithSupersampling) {
  // A tilted wall edge: occluded where ω·m > 0.3 for a fixed oblique m.
  const dvec3 m = glm::normalize(dvec3(0.8, 0.5, 0.3));
  auto occluded = [&](const dvec3&, const dvec3& w) { return glm::dot(w, m) > 0.3; };
  for (int s : {1, 2, 4}) {
    const VertexSdf sdf = vertex_sdf(SurfaceFrame{}, dvec3(0), 128, s, occluded);
    const SdfGradient g = sdf_gradient(sdf.d, sdf.h, false);
    // Exact gradient direction at a cell: of the smooth boundary function f = 0.3 − ω·m in (θ, φ),
    // only meaningful away from the boundary's medial axis; compare within 0.3 rad of the edge.
    double sum = 0, worst = 0;
    int count = 0;
    for (int i = 4; i < 124; ++i)
      for (int j = 4; j < 124; ++j) {
        const double th = cell_centre(-kPi / 2, sdf.h, i), ph = cell_centre(-kPi / 2, sdf.h, j);
        const double dd = sdf.d.at(i, j);
        if (std::abs(dd) < 3 * sdf.h || std::abs(dd) > 0.3) continue;
        const double e = 1e-6;
        auto f = [&](double t, double p) { return 0.3 - glm::dot(direction_from_angles(SurfaceFrame{}, t, p), m); };
        const double ft = (f(th + e, ph) - f(th - e, ph)) / (2 * e), fp = (f(th, ph + e) - f(th, ph - e)) / (2 * e);
        // Only cells whose nearest boundary is the wall edge (not the horizon): d ≈ f/|∇f|.
        if (std::abs(dd - f(th, ph) / std::hypot(ft, fp)) > 2 * sdf.h) continue;
        // Near the edge, ∇d ∥ ∇f (both increase into the visible side).
        const double c = (g.d_theta.at(i, j) * ft + g.d_phi.at(i, j) * fp) /
                         (std::hypot(g.d_theta.at(i, j), g.d_phi.at(i, j)) * std::hypot(ft, fp));
        const double ang = std::acos(std::clamp(c, -1.0, 1.0));
        sum += ang, worst = std::max(worst, ang), ++count;
      }
    std::printf("∇d vs boundary normal, supersample %d (%d² fine): mean %.2f°, max %.2f° over %d cells\n", s,
                128 * s, sum / count * 180 / kPi, worst * 180 / kPi, count);
  }
}

TEST(VisibilityBench, SigmoidGainTableFit) {
  SigmoidGainTableSpec spec;
  if (const char* full = std::getenv("WEFT_BENCH_PAPER_KAPPA"); full && std::atoi(full))
    spec.sigma_l_count = 32, spec.sigma_prime_count = 32, spec.beta_count = 64;
  auto t0 = Clock::now();
  const SigmoidGainTable table = fit_sigmoid_gain_table(spec);
  const double t_fit = seconds_since(t0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (int t = 0; t < 400; ++t) {
    const double sl = spec.sigma_min * std::pow(spec.sigma_max / spec.sigma_min, u(rng));
    const double sp = spec.sigma_min * std::pow(spec.sigma_max / spec.sigma_min, u(rng));
    const double beta = u(rng) * 2 * kPi;
    const CircularGaussianCdf cl(sl), cp(sp);
    const double s = gaussian_spread(sl, sp, std::cos(beta), std::sin(beta));
    for (int i = 0; i <= 40; ++i) {
      const double d = (-4 + 8.0 * i / 40) * s;
      worst = std::max(worst, std::abs(table.h(sl, sp, d, std::cos(beta), std::sin(beta)) -
                                       occluded_ratio_h(cl, cp, d, std::cos(beta), std::sin(beta))));
    }
  }
  std::printf("κ table %d×%d×%d over σ ∈ [%.4f, %.4f]: fit %.1f s, max |sigmoid − H| at nodes %.5f, "
              "off nodes (400 random σ_l, σ', ∇d) %.5f\n",
              spec.sigma_l_count, spec.sigma_prime_count, spec.beta_count, spec.sigma_min, spec.sigma_max, t_fit,
              table.max_fit_error(), worst);
}
