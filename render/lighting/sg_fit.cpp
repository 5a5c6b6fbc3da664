#include "lighting/sg_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "lighting/compact_source.h"
#include "lighting/nnls.h"

namespace weft {

namespace {
using glm::dvec3;
constexpr double kPi = std::numbers::pi;

// The map on a grid: texel-centre directions, solid angles, radiance; and, when the fit weighs
// the irradiance, its nine band-limited rows (see irradiance_rows).
struct Samples {
  std::vector<dvec3> d;
  std::vector<double> omega;
  std::vector<dvec3> L;
  Eigen::MatrixXd U;   // N × 9: U_ij = √w Â_l Ω_i Y_j(d_i), empty when the weight is 0
  Eigen::MatrixXd UL;  // 9 × 3: Σ_i U_ij L_i, the map's rows
  size_t size() const { return d.size(); }
  bool has_rows() const { return U.cols() > 0; }
};

// Real spherical harmonics of bands 0..2 and the clamped cosine's coefficients Â_l (Ramamoorthi
// & Hanrahan 2001): E(n) = Σ_j Â_l(j) L_j Y_j(n), exact for a map limited to those bands; odd
// bands above 1 do not reach E at all, and band 4's Â_4 = π/24 is 1/24 of band 0's (left to
// the radiance term).
std::array<double, 9> sh9(const dvec3& d) {
  return {0.282095,
          0.488603 * d.y, 0.488603 * d.z, 0.488603 * d.x,
          1.092548 * d.x * d.y, 1.092548 * d.y * d.z, 0.315392 * (3.0 * d.z * d.z - 1.0),
          1.092548 * d.x * d.z, 0.546274 * (d.x * d.x - d.y * d.y)};
}
constexpr std::array<double, 9> kCosineBand = {kPi, 2.0 * kPi / 3.0, 2.0 * kPi / 3.0, 2.0 * kPi / 3.0,
                                               kPi / 4.0, kPi / 4.0, kPi / 4.0, kPi / 4.0, kPi / 4.0};

// The irradiance term of the objective, w ∫‖E(n) − E_S(n)‖² dn over all normals, is by
// Parseval Σ_j w Â_l² (L_j − S_j)² with L_j = Σ_i Ω_i Y_j(d_i) L_i: nine more least-squares rows
// per channel, each a fixed linear combination of the texels' residuals. They enter every sum
// of the fit as nine extra samples would, so the amplitudes and the LM see them at no real cost.
void irradiance_rows(Samples& s, double weight) {
  if (!(weight > 0.0)) return;
  const Eigen::Index n = static_cast<Eigen::Index>(s.size());
  s.U.resize(n, 9);
  s.UL = Eigen::MatrixXd::Zero(9, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto y = sh9(s.d[i]);
    for (int j = 0; j < 9; ++j) {
      s.U(i, j) = std::sqrt(weight) * kCosineBand[j] * s.omega[i] * y[j];
      for (int c = 0; c < 3; ++c) s.UL(j, c) += s.U(i, j) * s.L[i][c];
    }
  }
}

Samples samples_of(const EnvMap& m, double irradiance_weight = 0.0) {
  Samples s;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      s.d.push_back(m.direction(x, y));
      s.omega.push_back(m.solid_angle(y));
      s.L.push_back(dvec3(m.at(x, y)));
    }
  irradiance_rows(s, irradiance_weight);
  return s;
}

double luminance(const dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

double lobe(const SphericalGaussian& g, const dvec3& d) { return std::exp(g.sharpness * (glm::dot(d, g.axis) - 1.0)); }

// ∫ G(ω)² dω over the sphere for a unit-amplitude lobe: π(1 − e^{−4λ})/λ.
double lobe_norm2(double lambda) { return kPi * -std::expm1(-4.0 * lambda) / lambda; }

// Radiant power of a lobe, for ordering: μ · 2π(1 − e^{−2λ})/λ.
double lobe_power(const SphericalGaussian& g) {
  return luminance(g.amplitude) * 2.0 * kPi * -std::expm1(-2.0 * g.sharpness) / g.sharpness;
}

// Power-keeping change of sharpness: μ ∫G dω stays, ∫G dω = 2π(1 − e^{−2λ})/λ.
SphericalGaussian with_sharpness(SphericalGaussian g, double lambda) {
  const double before = -std::expm1(-2.0 * g.sharpness) / g.sharpness;
  const double after = -std::expm1(-2.0 * lambda) / lambda;
  g.amplitude *= before / after;
  g.sharpness = lambda;
  return g;
}
// A lobe convolved with a unit SG kernel of sharpness λ_b is close to a lobe of sharpness
// λλ_b/(λ + λ_b) with the same power (exact in the narrow-lobe limit); and back.
SphericalGaussian blurred_lobe(const SphericalGaussian& g, double lambda_b) {
  return with_sharpness(g, g.sharpness * lambda_b / (g.sharpness + lambda_b));
}
SphericalGaussian sharpened_lobe(const SphericalGaussian& g, double lambda_b, double max_lambda) {
  const double lambda = g.sharpness < lambda_b * max_lambda / (lambda_b + max_lambda)
                            ? g.sharpness * lambda_b / (lambda_b - g.sharpness)
                            : max_lambda;
  return with_sharpness(g, lambda);
}

double cost(const Samples& s, std::span<const SphericalGaussian> sgs) {
  double sum = 0.0;
  Eigen::MatrixXd rows = s.has_rows() ? Eigen::MatrixXd(-s.UL) : Eigen::MatrixXd();
  for (size_t i = 0; i < s.size(); ++i) {
    const dvec3 model = evaluate(sgs, s.d[i]);
    const dvec3 r = model - s.L[i];
    sum += s.omega[i] * glm::dot(r, r);
    if (s.has_rows())
      for (int j = 0; j < 9; ++j)
        for (int c = 0; c < 3; ++c) rows(j, c) += s.U(static_cast<Eigen::Index>(i), j) * model[c];
  }
  return s.has_rows() ? sum + rows.squaredNorm() : sum;
}

// Best non-negative amplitudes for fixed axes and sharpnesses (per channel NNLS).
void solve_amplitudes(const Samples& s, SgLighting& sgs) {
  const Eigen::Index K = static_cast<Eigen::Index>(sgs.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(K, K);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(K, 3);
  Eigen::VectorXd g(K);
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(9, K);  // the irradiance rows of each lobe
  for (size_t i = 0; i < s.size(); ++i) {
    for (Eigen::Index k = 0; k < K; ++k) g(k) = lobe(sgs[k], s.d[i]);
    A.selfadjointView<Eigen::Lower>().rankUpdate(g, s.omega[i]);
    for (int c = 0; c < 3; ++c) b.col(c) += (s.omega[i] * s.L[i][c]) * g;
    if (s.has_rows()) Z += s.U.row(static_cast<Eigen::Index>(i)).transpose() * g.transpose();
  }
  A = A.selfadjointView<Eigen::Lower>();
  if (s.has_rows()) {
    A += Z.transpose() * Z;
    b += Z.transpose() * s.UL;
  }
  for (int c = 0; c < 3; ++c) {
    const Eigen::VectorXd mu = solve_nnls(A, b.col(c));
    for (Eigen::Index k = 0; k < K; ++k) sgs[k].amplitude[c] = mu(k);
  }
}

// The fit grid seen through the narrowest lobe the fit may use: each texel's power Ω_j L_j is
// spread over its neighbours with a unit SG kernel of sharpness λ_b, normalised per source texel
// so that power is kept exactly. Without this, a source smaller than a lobe (a sun, a spot lamp)
// would be fitted in least squares by a lobe with twice its power (⟨δ,G⟩/⟨G,G⟩·∫G = 2 for
// a Gaussian G); blurred, it is itself a lobe of sharpness λ_b and is fitted with its power.
EnvMap blur_to_lobe(const EnvMap& m, double lambda_b) {
  const double reach = 3.5 / std::sqrt(lambda_b);  // radians; the kernel is e^{-6} there
  const int dy = static_cast<int>(std::ceil(reach / (kPi / m.height))) + 1;
  std::vector<dvec3> power(m.texels.size(), dvec3(0.0));
  std::vector<double> row_omega(m.height);
  for (int y = 0; y < m.height; ++y) row_omega[y] = m.solid_angle(y);
  // The kernel around a texel depends on its row only (turning about +Z maps the row onto
  // itself): one set of (row, column offset, weight) taps per row, from its first texel.
  struct Tap {
    int row, offset;
    double k;
  };
  std::vector<Tap> taps;
  for (int y = 0; y < m.height; ++y) {
    const dvec3 dj = m.direction(0, y);
    taps.clear();
    double z = 0.0;
    for (int ty = std::max(0, y - dy); ty <= std::min(m.height - 1, y + dy); ++ty) {
      const double elevation = kPi * (0.5 - (ty + 0.5) / m.height);
      const double cos_e = std::max(std::cos(elevation), 1e-3);
      const int dx = static_cast<int>(std::ceil(reach / cos_e / (2.0 * kPi / m.width))) + 1;
      const int lo = 2 * dx + 1 >= m.width ? 0 : -dx, hi = 2 * dx + 1 >= m.width ? m.width - 1 : dx;
      for (int off = lo; off <= hi; ++off) {
        const int wx = ((off % m.width) + m.width) % m.width;
        const double k = row_omega[ty] * std::exp(lambda_b * (glm::dot(m.direction(wx, ty), dj) - 1.0));
        taps.push_back({ty, off, k});
        z += k;
      }
    }
    for (int x = 0; x < m.width; ++x) {
      const dvec3 p = row_omega[y] * dvec3(m.at(x, y)) / z;
      for (const Tap& t : taps)
        power[static_cast<size_t>(t.row) * m.width + ((x + t.offset) % m.width + m.width) % m.width] += t.k * p;
    }
  }
  EnvMap out(m.width, m.height);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      const size_t t = static_cast<size_t>(y) * m.width + x;
      out.texels[t] = glm::vec3(power[t] / row_omega[y]);
    }
  return out;
}

// Step 1: greedy matching pursuit on a 32×16 grid. Adds lobes to `sgs` until it holds `count`.
// Scores and amplitudes are computed on the same grid, so at the NNLS optimum no existing lobe
// scores again (its residual projection is ≤ 0): no duplicates. Candidate axes: the grid's
// texel centres plus the brightest texel of the residual on the finer fit grid, so that a small
// bright source is placed to within a fit-grid texel.
void seed_lobes(const EnvMap& map, const Samples& fine, int count, double min_lambda, double max_lambda,
                SgLighting& sgs) {
  if (static_cast<int>(sgs.size()) >= count) return;  // a full warm start
  const Samples coarse = samples_of(resample(map, 32, 16));  // the sizes of the table below
  const size_t n = coarse.size();
  // Candidate sharpnesses: doubling from min to what the 32×16 grid resolves, (16/π)² ≈ 26;
  // LM sharpens further on the fit grid.
  const double seed_max = std::min(max_lambda, std::pow(16.0 / kPi, 2));
  std::vector<double> lambdas;
  for (double l = std::max(min_lambda, 0.25); l <= seed_max * 1.0001; l *= 2.0) lambdas.push_back(l);
  if (lambdas.empty() || lambdas.back() < seed_max) lambdas.push_back(seed_max);

  // exp(λ(d_a·d_i − 1)) for every candidate axis a (texel centres), texel i and λ. It depends on
  // the two rows and the column difference only (turning about +Z), so it is tabulated as
  // kernel[l][(row_a·H + row_i)·W + (col_i − col_a) mod W].
  constexpr int W = 32, H = 16;
  std::vector<double> kernel(lambdas.size() * H * H * W);
  for (size_t l = 0; l < lambdas.size(); ++l)
    for (int ra = 0; ra < H; ++ra)
      for (int ri = 0; ri < H; ++ri)
        for (int dc = 0; dc < W; ++dc)
          kernel[((l * H + ra) * H + ri) * W + dc] =
              std::exp(lambdas[l] * (glm::dot(coarse.d[ra * W], coarse.d[ri * W + dc]) - 1.0));

  // Score of a unit lobe against the residual projections p_c = ⟨R_c, G⟩: the error reduction of
  // adding it with the best non-negative amplitude, Σ_c max(p_c, 0)² / ‖G‖².
  auto score = [](const dvec3& p, double lambda) {
    const dvec3 q = glm::max(p, dvec3(0.0));
    return glm::dot(q, q) / lobe_norm2(lambda);
  };

  while (static_cast<int>(sgs.size()) < count) {
    std::vector<dvec3> residual(n);  // Ω_i (L_i − S(d_i)) on the seed grid
    for (size_t i = 0; i < n; ++i) residual[i] = coarse.omega[i] * (coarse.L[i] - evaluate(sgs, coarse.d[i]));
    size_t peak = 0;
    double peak_value = -1e300;
    for (size_t i = 0; i < fine.size(); ++i) {
      const double v = luminance(fine.L[i] - evaluate(sgs, fine.d[i]));
      if (v > peak_value) peak_value = v, peak = i;
    }

    SphericalGaussian best{dvec3(0, 0, 1), min_lambda, dvec3(0.0)};
    double best_score = 0.0;
    for (size_t l = 0; l < lambdas.size(); ++l) {
      for (size_t a = 0; a < n; ++a) {
        dvec3 p(0.0);
        const int ra = static_cast<int>(a) / W, ca = static_cast<int>(a) % W;
        for (int ri = 0; ri < H; ++ri) {
          const double* k = &kernel[((l * H + ra) * H + ri) * W];
          const dvec3* r = &residual[static_cast<size_t>(ri) * W];
          for (int ci = 0; ci < W; ++ci) p += k[(ci - ca) & (W - 1)] * r[ci];
        }
        const double s = score(p, lambdas[l]);
        if (s > best_score) best_score = s, best = {coarse.d[a], lambdas[l], glm::max(p, dvec3(0.0)) / lobe_norm2(lambdas[l])};
      }
      const SphericalGaussian g{fine.d[peak], lambdas[l], dvec3(1.0)};
      dvec3 p(0.0);
      for (size_t i = 0; i < n; ++i) p += lobe(g, coarse.d[i]) * residual[i];
      const double s = score(p, lambdas[l]);
      if (s > best_score) best_score = s, best = {g.axis, lambdas[l], glm::max(p, dvec3(0.0)) / lobe_norm2(lambdas[l])};
    }
    // With nothing left to explain (e.g. a black map) `best` is an idle lobe, so the count holds.
    sgs.push_back(best);
    solve_amplitudes(coarse, sgs);
  }
}

// Step 2: projected Levenberg–Marquardt. Parameters per lobe: two tangent-plane rotations of ξ,
// s = log λ, μ_r, μ_g, μ_b. Residuals r_{i,c} = √Ω_i (Σ_k μ_kc g_k(d_i) − L_c(d_i)).
// The channels share the geometry, so JᵀJ is assembled from the N × 4K matrix
// X_i = √Ω_i [∂g_k/∂(a, b, s) …, g_k …] (one row per texel, not per texel and channel):
//   (JᵀJ)_{geo k, geo l} = (μ_k·μ_l) (XᵀX)_{kl},  (JᵀJ)_{geo k, μ_lc} = μ_kc (XᵀX)_{k,l},
//   (JᵀJ)_{μ_kc, μ_lc'} = δ_cc' (XᵀX)_{kl}  — seven times less work than forming J.
int refine_lobes(const Samples& s, double min_lambda, double max_lambda, int max_iterations, SgLighting& sgs) {
  const Eigen::Index K = static_cast<Eigen::Index>(sgs.size());
  const Eigen::Index P = 6 * K;
  const Eigen::Index N = static_cast<Eigen::Index>(s.size());
  Eigen::MatrixXd X(N, 4 * K);
  Eigen::MatrixXd R(N, 3);
  std::vector<dvec3> t1(K), t2(K);
  // U / √Ω, so that Uᵀ applied to X's √Ω-weighted rows gives the rows of the unweighted sums.
  Eigen::MatrixXd U_unweighted;
  if (s.has_rows()) {
    U_unweighted = s.U;
    for (Eigen::Index i = 0; i < N; ++i) U_unweighted.row(i) /= std::sqrt(s.omega[i]);
  }
  double current = cost(s, sgs);
  double damping = 1e-3;
  int iteration = 0;
  for (; iteration < max_iterations; ++iteration) {
    for (Eigen::Index k = 0; k < K; ++k) {
      const dvec3& xi = sgs[k].axis;
      const dvec3 helper = std::abs(xi.z) < 0.9 ? dvec3(0, 0, 1) : dvec3(1, 0, 0);
      t1[k] = glm::normalize(glm::cross(xi, helper));
      t2[k] = glm::cross(xi, t1[k]);
    }
    for (Eigen::Index i = 0; i < N; ++i) {
      const double w = std::sqrt(s.omega[i]);
      const dvec3& d = s.d[i];
      dvec3 model(0.0);
      for (Eigen::Index k = 0; k < K; ++k) {
        const SphericalGaussian& g = sgs[k];
        const double cosine = glm::dot(d, g.axis);
        const double e = std::exp(g.sharpness * (cosine - 1.0));
        model += g.amplitude * e;
        const double we = w * e;
        X(i, 3 * k + 0) = we * g.sharpness * glm::dot(d, t1[k]);
        X(i, 3 * k + 1) = we * g.sharpness * glm::dot(d, t2[k]);
        X(i, 3 * k + 2) = we * g.sharpness * (cosine - 1.0);  // ∂/∂ log λ
        X(i, 3 * K + k) = we;
      }
      for (int c = 0; c < 3; ++c) R(i, c) = w * (model[c] - s.L[i][c]);
    }
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(4 * K, 4 * K);
    G.selfadjointView<Eigen::Lower>().rankUpdate(X.transpose());
    G = G.selfadjointView<Eigen::Lower>();
    Eigen::MatrixXd XtR = X.transpose() * R;
    if (s.has_rows()) {
      // The irradiance rows: Z = Uᵀ D and their residuals Uᵀ(S − L), with D = X / √Ω unweighted.
      const Eigen::MatrixXd Z = U_unweighted.transpose() * X;
      const Eigen::MatrixXd RZ = U_unweighted.transpose() * R;
      G += Z.transpose() * Z;
      XtR += Z.transpose() * RZ;
    }

    Eigen::MatrixXd JtJ = Eigen::MatrixXd::Zero(P, P);
    Eigen::VectorXd Jtr = Eigen::VectorXd::Zero(P);
    for (Eigen::Index k = 0; k < K; ++k) {
      const dvec3& mk = sgs[k].amplitude;
      for (int p = 0; p < 3; ++p) {
        for (int c = 0; c < 3; ++c) Jtr(6 * k + p) += mk[c] * XtR(3 * k + p, c);
        for (Eigen::Index l = 0; l < K; ++l) {
          const dvec3& ml = sgs[l].amplitude;
          for (int q = 0; q < 3; ++q) JtJ(6 * k + p, 6 * l + q) = glm::dot(mk, ml) * G(3 * k + p, 3 * l + q);
          for (int c = 0; c < 3; ++c) {
            JtJ(6 * k + p, 6 * l + 3 + c) = mk[c] * G(3 * k + p, 3 * K + l);
            JtJ(6 * l + 3 + c, 6 * k + p) = JtJ(6 * k + p, 6 * l + 3 + c);
          }
        }
      }
      for (int c = 0; c < 3; ++c) {
        Jtr(6 * k + 3 + c) = XtR(3 * K + k, c);
        for (Eigen::Index l = 0; l < K; ++l) JtJ(6 * k + 3 + c, 6 * l + 3 + c) = G(3 * K + k, 3 * K + l);
      }
    }
    const Eigen::VectorXd diag = JtJ.diagonal().cwiseMax(1e-12 * (JtJ.diagonal().maxCoeff() + 1e-300));

    bool improved = false;
    for (int attempt = 0; attempt < 12 && !improved; ++attempt) {
      Eigen::MatrixXd H = JtJ;
      H.diagonal() += damping * diag;
      const Eigen::VectorXd delta = H.ldlt().solve(-Jtr);
      SgLighting trial = sgs;
      for (Eigen::Index k = 0; k < K; ++k) {
        SphericalGaussian& g = trial[k];
        // Rotate the axis within its tangent plane, at most ~30° per step.
        double a = delta(6 * k), b = delta(6 * k + 1);
        const double len = std::hypot(a, b);
        if (len > 0.5) a *= 0.5 / len, b *= 0.5 / len;
        g.axis = glm::normalize(g.axis + a * t1[k] + b * t2[k]);
        const double log_lambda = std::log(g.sharpness) + std::clamp(delta(6 * k + 2), -2.0, 2.0);
        g.sharpness = std::clamp(std::exp(log_lambda), min_lambda, max_lambda);
        for (int c = 0; c < 3; ++c) g.amplitude[c] = std::max(0.0, g.amplitude[c] + delta(6 * k + 3 + c));
      }
      const double trial_cost = cost(s, trial);
      if (std::isfinite(trial_cost) && trial_cost < current) {
        const double gain = (current - trial_cost) / current;
        sgs = std::move(trial);
        current = trial_cost;
        damping = std::max(damping / 3.0, 1e-9);
        improved = true;
        if (gain < 1e-7) return iteration + 1;
      } else {
        damping *= 4.0;
      }
    }
    if (!improved) return iteration + 1;
  }
  return iteration;
}
}  // namespace

SgLighting fit_sgs(const EnvMap& map, const SgFitOptions& options, std::span<const SphericalGaussian> initial,
                   SgFitStats* stats) {
  if (options.count < 1 || options.count > 64)
    throw std::invalid_argument("SG fit: count must be in [1, 64], got " + std::to_string(options.count));
  if (options.grid_width < 16 || options.grid_width > 1024 || options.grid_width % 2 != 0)
    throw std::invalid_argument("SG fit: grid width must be even and in [16, 1024], got " +
                                std::to_string(options.grid_width));
  if (!(options.min_sharpness > 0.0) || !(options.max_sharpness > options.min_sharpness) ||
      !std::isfinite(options.max_sharpness))
    throw std::invalid_argument("SG fit: need 0 < min_sharpness < max_sharpness");
  if (options.max_iterations < 0) throw std::invalid_argument("SG fit: max_iterations must be >= 0");
  if (!(options.irradiance_weight >= 0.0) || !std::isfinite(options.irradiance_weight))
    throw std::invalid_argument("SG fit: irradiance_weight must be finite and >= 0");
  if (map.width < 2 || map.height < 1) throw std::invalid_argument("SG fit: empty map");

  const int grid_height = options.grid_width / 2;
  // The narrowest lobe the fit grid resolves (σ = 1/√λ one texel, π/H) is also the blur of the
  // fit grid; fitted lobes are then sharpened back (below) up to max_sharpness.
  const double lambda_b = std::pow(grid_height / kPi, 2);
  const double max_lambda = lambda_b;
  const double min_lambda = std::min(options.min_sharpness, lambda_b / 4.0);

  // A sun gets one lobe of its own, at its direction with its power; the rest of the map
  // (the source's texels set to the background around it) is fitted by the others.
  EnvMap rest;
  std::optional<SphericalGaussian> source_lobe;
  if (options.count >= 2 && options.single_lobe_source) {
    if (const auto src = find_compact_source(map, {}, &rest)) {
      // A uniform disc of radius r has spread r²/4 (small r), the SG of the same spread λ = 4/r².
      const double lambda = std::clamp(src->spread > 0.0 ? 1.0 / src->spread : options.max_sharpness,
                                       options.min_sharpness, options.max_sharpness);
      source_lobe = SphericalGaussian{src->direction, lambda, src->power / sg_sphere_integral(lambda)};
    }
  }
  const EnvMap& fitted_map = source_lobe ? rest : map;
  const int count = options.count - (source_lobe ? 1 : 0);
  const Samples fine = samples_of(blur_to_lobe(resample(fitted_map, options.grid_width, grid_height), lambda_b),
                                  options.irradiance_weight);

  SgLighting sgs;
  for (const SphericalGaussian& g0 : initial) {
    SphericalGaussian g = g0;
    const double len = glm::length(g.axis);
    if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(g.sharpness)) continue;  // unusable lobe
    g.axis /= len;
    g = blurred_lobe(g, lambda_b);
    g.sharpness = std::clamp(g.sharpness, min_lambda, max_lambda);
    for (int c = 0; c < 3; ++c) g.amplitude[c] = std::isfinite(g.amplitude[c]) ? std::max(0.0, g.amplitude[c]) : 0.0;
    sgs.push_back(g);
  }
  if (source_lobe && !sgs.empty()) {
    // The warm start's lobe on the source (the last fit's sun) is replaced by the source's.
    auto nearest = std::max_element(sgs.begin(), sgs.end(), [&](auto& a, auto& b) {
      return glm::dot(a.axis, source_lobe->axis) < glm::dot(b.axis, source_lobe->axis);
    });
    if (glm::dot(nearest->axis, source_lobe->axis) > std::cos(5.0 * kPi / 180.0)) sgs.erase(nearest);
  }
  if (static_cast<int>(sgs.size()) > count) {
    std::stable_sort(sgs.begin(), sgs.end(), [](auto& a, auto& b) { return lobe_power(a) > lobe_power(b); });
    sgs.resize(count);
  }
  if (!sgs.empty()) solve_amplitudes(fine, sgs);
  seed_lobes(fitted_map, fine, count, min_lambda, max_lambda, sgs);
  solve_amplitudes(fine, sgs);

  const double initial_cost = cost(fine, sgs);
  const int iterations = refine_lobes(fine, min_lambda, max_lambda, options.max_iterations, sgs);
  solve_amplitudes(fine, sgs);
  const double final_cost = cost(fine, sgs);
  for (auto& g : sgs) g = sharpened_lobe(g, lambda_b, options.max_sharpness);
  if (source_lobe) sgs.push_back(*source_lobe);
  std::stable_sort(sgs.begin(), sgs.end(), [](auto& a, auto& b) { return lobe_power(a) > lobe_power(b); });
  if (stats) *stats = {iterations, initial_cost, final_cost, options.max_sharpness};
  return sgs;
}

}  // namespace weft
