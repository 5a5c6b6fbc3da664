#include "methods/mizutani/mizutani.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/circular_gaussian.h"

namespace weft {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kPowers = 11;  // x^0..x^10: the volume lobe's (1 − F_r)² reaches degree 10
constexpr int kNodes = kMizutaniThetaSegments + 1;

// Schlick in x = cos(φ_d/2) at c = cos θ_d (Eq. 12–13): F_r = Σ_l surf[l] x^l (l ≤ 5) and
// (1 − F_r)² = Σ_m vol[m] x^m (m ≤ 10).
void schlick_polynomials(double f0, double c, std::array<double, 6>& surf, std::array<double, kPowers>& vol) {
  static constexpr double binom5[6] = {1, 5, 10, 10, 5, 1};
  std::array<double, 6> transmit{};  // 1 − F_r = −(1 − F_0) Σ_{l≥1} C(5,l)(−c)^l x^l
  double p = 1.0;
  for (int l = 0; l < 6; ++l, p *= -c) {
    surf[l] = (1.0 - f0) * binom5[l] * p;
    transmit[l] = l == 0 ? 0.0 : -surf[l];
  }
  surf[0] += f0;
  vol.fill(0.0);
  for (int a = 1; a < 6; ++a)
    for (int b = 1; b < 6; ++b) vol[a + b] += transmit[a] * transmit[b];
}

// Σ over the 6 segments of ∫ g(θ;μ,σ) h(θ) dθ with h linear between its node values.
double piecewise_linear_integral(const std::array<double, kNodes>& h, double mu, double sigma) {
  constexpr double step = kPi / kMizutaniThetaSegments;
  double sum = 0.0;
  for (int s = 0; s < kMizutaniThetaSegments; ++s) {
    const double a = -0.5 * kPi + s * step;
    const SegmentMoments m = gaussian_segment_moments(a, a + step, mu, sigma);
    sum += h[s] * m.m0 + (h[s + 1] - h[s]) / step * m.m1;
  }
  return sum;
}

}  // namespace

SegmentMoments gaussian_segment_moments(double a, double b, double mu, double sigma) {
  if (!(sigma < 1e4)) return {b - a, 0.5 * (b - a) * (b - a)};
  const double za = (a - mu) / sigma, zb = (b - mu) / sigma;
  SegmentMoments m;
  m.m0 = 0.5 * std::sqrt(kPi) * sigma * (std::erf(zb) - std::erf(za));
  // ∫(θ − a)g = (μ − a)∫g + ∫(θ − μ)g, the latter (σ²/2)(e^{−za²} − e^{−zb²}).
  m.m1 = (mu - a) * m.m0 + 0.5 * sigma * sigma * (std::exp(-za * za) - std::exp(-zb * zb));
  return m;
}

MizutaniShading mizutani_shading(const ThreadParams& p, const ThreadFrame& tf, const dvec3& wo,
                                 const SphericalGaussian& g, const AzimuthalTable& azimuthal) {
  const double f0 = ((p.eta - 1.0) / (p.eta + 1.0)) * ((p.eta - 1.0) / (p.eta + 1.0));
  const double gs = seed_bandwidth_from_std_dev(p.gamma_s), gv = seed_bandwidth_from_std_dev(p.gamma_v);
  const SgCircularSplit sg = split_sg(g, tf);  // Eq. 10
  const FiberAngles o = fiber_angles(tf, wo);
  const double cos_k = std::cos(sg.theta_k);

  // h at the segment ends (Eq. 16): φ_i integrals from the table at σ'_k(θ_i). At θ_i = ±π/2
  // h carries cos²θ_i = 0: those two ends stay 0 and cost no lookups.
  std::array<double, kNodes> h_surf{}, h_vol{};
  for (int i = 1; i + 1 < kNodes; ++i) {
    const double theta = -0.5 * kPi + i * kPi / kMizutaniThetaSegments;
    const double cos_t = std::max(std::cos(theta), 0.0);
    const double lambda_prime = g.sharpness * cos_t * cos_k;
    const double cos_d = std::cos(0.5 * (theta - o.theta));
    std::array<double, 6> cs;
    std::array<double, kPowers> cv;
    schlick_polynomials(f0, cos_d, cs, cv);
    double sum_s = 0.0, sum_v = 0.0;
    for (int m = 0; m < kPowers; ++m) {
      const double tm = azimuthal.value(m, o.phi, sg.phi_k, lambda_prime);
      if (m >= 1 && m <= 6) sum_s += cs[m - 1] * tm;  // f_rs carries one more cos(φ_d/2)
      sum_v += cv[m] * tm;
    }
    // dω = cos θ dθ dφ: the second cos θ beside the model's own.
    const double geo = cos_t * cos_t / std::max(cos_d * cos_d, kModelDenominatorFloor);
    h_surf[i] = geo * sum_s;
    h_vol[i] = geo * sum_v / std::max(cos_t + std::cos(o.theta), kModelDenominatorFloor);
  }
  const ScaledCircularGaussian light{1.0, sg.theta_k, sg.sigma_k};
  const ScaledCircularGaussian ls = product(light, longitudinal_lobe_as_circular(o.theta, gs));  // Eq. 11
  const ScaledCircularGaussian lv = product(light, longitudinal_lobe_as_circular(o.theta, gv));
  const double i_surf = ls.alpha * piecewise_linear_integral(h_surf, ls.mu, ls.sigma);
  const double i_vol = (1.0 - p.kd) * lv.alpha * piecewise_linear_integral(h_vol, lv.mu, lv.sigma) +
                       p.kd * piecewise_linear_integral(h_vol, sg.theta_k, sg.sigma_k);
  return {std::max(i_surf, 0.0), std::max(i_vol, 0.0)};
}

MizutaniTerms mizutani_radiance(const ClothBsdf& bsdf, const WeightingTables& weights,
                                const AzimuthalTable& azimuthal, const SurfaceFrame& frame, const dvec3& wo,
                                std::span<const SphericalGaussian> sgs) {
  if (weights.tangent_samples[0] != bsdf.sample_count(0) || weights.tangent_samples[1] != bsdf.sample_count(1))
    throw std::invalid_argument("mizutani: weighting tables were baked for other tangent sample counts");
  if (azimuthal.settings.max_power < kPowers - 1)
    throw std::invalid_argument("mizutani: the azimuthal table must hold powers 0..10");
  MizutaniTerms out;
  if (glm::dot(wo, frame.n) <= 0.0) return out;
  auto local = [&](const dvec3& w) { return dvec3(glm::dot(w, frame.u), glm::dot(w, frame.v), glm::dot(w, frame.n)); };
  const dvec3 wo_local = local(wo);

  for (const SphericalGaussian& g : sgs) {
    const dvec3 xi_local = local(g.axis);
    int s = 0;
    for (int j = 0; j < 2; ++j) {
      const ThreadParams& p = bsdf.fabric().threads[j];
      const int n = bsdf.sample_count(j);
      dvec3 surf(0.0), vol(0.0);
      for (int k = 0; k < n; ++k, ++s) {
        const double T = weights.value(s, g.sharpness, xi_local, wo_local);  // Eq. 9
        if (T <= 0.0) continue;
        const MizutaniShading sh = mizutani_shading(p, thread_frame(frame, j, bsdf.tilt(j, k)), wo, g, azimuthal);
        surf += dvec3(T * sh.surface);
        vol += T * sh.volume * p.albedo;
      }
      out.surface += g.amplitude * surf / double(n);
      out.volume += g.amplitude * vol / double(n);
    }
  }
  out.radiance = out.surface + out.volume;
  return out;
}

}  // namespace weft
