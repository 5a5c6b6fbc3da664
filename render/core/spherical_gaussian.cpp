#include "core/spherical_gaussian.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;

// (1 − e^{−x})/x without cancellation; 1 at x = 0.
double one_minus_exp_over(double x) { return x == 0.0 ? 1.0 : -std::expm1(-x) / x; }

// Below this λ the clamped-cosine end values are summed as series: their closed forms cancel.
constexpr double kSeriesSharpness = 0.5;

// ∫_0^1 t·e^{λ(t−1)} dt: the clamped-cosine integral over 2π for c = +1.
// Closed form (1 − (1−e^{−λ})/λ)/λ; series Σ_j (−λ)^j/(j+2)!.
double upper_cosine_over_two_pi(double lambda) {
  if (lambda >= kSeriesSharpness) return (1.0 - one_minus_exp_over(lambda)) / lambda;
  double term = 0.5, sum = 0.0;  // j = 0: 1/2!
  for (int j = 0; j < 20; ++j) {
    sum += term;
    term *= -lambda / (j + 3);
  }
  return sum;
}

// e^{−λ}·∫_0^1 u·e^{−λu} du: the same for c = −1 (the lobe points into the lower hemisphere).
// Closed form e^{−λ}((1−e^{−λ})/λ − e^{−λ})/λ; series e^{−λ}·Σ_k (−λ)^k/(k!(k+2)).
double lower_cosine_over_two_pi(double lambda) {
  const double e = std::exp(-lambda);
  if (lambda >= kSeriesSharpness) return e * (one_minus_exp_over(lambda) - e) / lambda;
  double power = 1.0, sum = 0.0;  // (−λ)^k/k!
  for (int k = 0; k < 20; ++k) {
    sum += power / (k + 2);
    power *= -lambda / (k + 1);
  }
  return e * sum;
}

// Below this steepness the lerp factors are replaced by their t → 0 limits (linear in c).
constexpr double kSmallSteepness = 1e-6;
}  // namespace

glm::dvec3 evaluate(std::span<const SphericalGaussian> sgs, const glm::dvec3& w) {
  glm::dvec3 sum(0.0);
  for (const auto& g : sgs) sum += g(w);
  return sum;
}

double sg_bandwidth(double sharpness) { return std::sqrt(2.0 / sharpness); }
double sg_sharpness(double bandwidth) { return 2.0 / (bandwidth * bandwidth); }

double sg_sphere_integral(double sharpness) { return 4.0 * kPi * one_minus_exp_over(2.0 * sharpness); }

namespace {
// Tokuyoshi 2022's lerp factor between the c = −1 and c = +1 ends, with its fitted steepness.
double hemisphere_steepness(double lambda) {
  constexpr double A = 0.6517328826907056, B = 1.3418280033141288, C = 7.2216687798956709;
  return lambda * std::sqrt((0.5 * lambda + A) / ((lambda + B) * lambda + C));
}
double hemisphere_lerp_factor(double lambda, double c) {
  const double t = hemisphere_steepness(lambda);
  return t < kSmallSteepness ? 0.5 + 0.5 * c : 0.5 + 0.5 * std::erf(t * c) / std::erf(t);
}
}  // namespace

double sg_hemisphere_integral(double sharpness, double cos_axis_normal) {
  const double lambda = sharpness, c = glm::clamp(cos_axis_normal, -1.0, 1.0);
  // Exact ends: the lobe centred on the pole (c = 1) or on the antipode (c = −1).
  const double upper = 2.0 * kPi * one_minus_exp_over(lambda);
  const double lower = std::exp(-lambda) * upper;
  return lower + (upper - lower) * hemisphere_lerp_factor(lambda, c);
}

double sg_hemisphere_fraction(double sharpness, double cos_axis_normal) {
  return sg_hemisphere_fraction(sg_hemisphere_terms(sharpness), cos_axis_normal);
}

SgHemisphereTerms sg_hemisphere_terms(double sharpness) {
  const double lambda = sharpness, t = hemisphere_steepness(lambda);
  return {t, t < kSmallSteepness ? 0.0 : 1.0 / std::erf(t), std::exp(-lambda)};
}

double sg_hemisphere_fraction(const SgHemisphereTerms& terms, double cos_axis_normal) {
  const double c = glm::clamp(cos_axis_normal, -1.0, 1.0), e = terms.exp_minus_lambda;
  const double lerp = terms.inverse_erf == 0.0 ? 0.5 + 0.5 * c : 0.5 + 0.5 * std::erf(terms.steepness * c) * terms.inverse_erf;
  return (e + (1.0 - e) * lerp) / (1.0 + e);
}

double sg_clamped_cosine_integral(double sharpness, double cos_axis_normal) {
  const double lambda = sharpness, c = glm::clamp(cos_axis_normal, -1.0, 1.0);
  const double upper = upper_cosine_over_two_pi(lambda);
  const double lower = lower_cosine_over_two_pi(lambda);
  // Tokuyoshi et al. 2024's fitted steepness t(λ).
  constexpr double A = 2.7360831611272558, B = 17.021297781741875, C = 4.0100826728510421,
                   D = 15.219156263147211, E = 76.087896272360737;
  const double t =
      lambda * std::sqrt(0.5 * ((lambda + A) * lambda + B) / (((lambda + C) * lambda + D) * lambda + E));
  double factor = 0.5 + 0.5 * c;
  if (t >= kSmallSteepness) {
    // ∫ of a unit Gaussian CDF-shaped weight against the ramp max(c, 0), in closed form.
    const double tc = t * c;
    factor = 0.5 * (c * std::erfc(-tc) + std::erfc(t)) -
             0.5 / std::sqrt(kPi) * std::exp(-tc * tc) * std::expm1(t * t * (c * c - 1.0)) / t;
  }
  return 2.0 * kPi * (lower + (upper - lower) * factor);
}

glm::dvec3 integral(const SphericalGaussian& g) { return g.amplitude * sg_sphere_integral(g.sharpness); }

glm::dvec3 hemisphere_integral(const SphericalGaussian& g, const glm::dvec3& n) {
  return g.amplitude * sg_hemisphere_integral(g.sharpness, glm::dot(g.axis, n));
}

glm::dvec3 irradiance(const SphericalGaussian& g, const glm::dvec3& n) {
  return g.amplitude * sg_clamped_cosine_integral(g.sharpness, glm::dot(g.axis, n));
}

double horizon_sharpness_for_mean_cosine(double mean_cosine, double min_sharpness) {
  auto mean_at = [](double log_lambda) {
    const double l = std::exp(log_lambda);
    return sg_clamped_cosine_integral(l, 0.0) / sg_hemisphere_integral(l, 0.0);
  };
  double lo = std::log(min_sharpness), hi = lo + kHorizonSharpnessLogRange;
  if (mean_at(lo) <= mean_cosine) return min_sharpness;
  for (int i = 0; i < kHorizonSharpnessSteps; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mean_at(mid) > mean_cosine ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

double horizon_sliver_weight(double sharpness) {
  return std::clamp(std::log(sharpness / kHorizonSliverFrom) / std::log(kHorizonSliverTo / kHorizonSliverFrom), 0.0,
                    1.0);
}

SphericalGaussian above_horizon(const SphericalGaussian& g, const glm::dvec3& n, double min_sharpness) {
  const double c = glm::dot(g.axis, n);
  if (c >= 0.0) return g;
  glm::dvec3 e = g.axis - c * n;
  const double s = glm::length(e);
  if (s > 1e-6) {
    e /= s;
  } else {  // the nadir: any horizon direction
    e = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  }
  SphericalGaussian out;
  out.axis = e;
  // A broad lobe's visible part: λ·s, and G's clamped-cosine integral.
  const double lambda_ring = std::max(g.sharpness * s, min_sharpness);
  const double scale_ring = sg_clamped_cosine_integral(g.sharpness, c) / sg_clamped_cosine_integral(lambda_ring, 0.0);
  const double w = horizon_sliver_weight(g.sharpness);
  if (w <= 0.0) {
    out.sharpness = lambda_ring;
    out.amplitude = g.amplitude * scale_ring;
    return out;
  }
  // A sharp lobe's sliver: G's power above the plane and its mean cosine there.
  const double power = sg_hemisphere_integral(g.sharpness, c);
  const double lambda_sliver =
      horizon_sharpness_for_mean_cosine(sg_clamped_cosine_integral(g.sharpness, c) / power, lambda_ring);
  const double scale_sliver = power / sg_hemisphere_integral(lambda_sliver, 0.0);
  out.sharpness = std::pow(lambda_ring, 1.0 - w) * std::pow(lambda_sliver, w);
  out.amplitude = g.amplitude * (std::pow(scale_ring, 1.0 - w) * std::pow(scale_sliver, w));
  return out;
}

SphericalGaussian product(const SphericalGaussian& a, const SphericalGaussian& b) {
  const glm::dvec3 m = a.sharpness * a.axis + b.sharpness * b.axis;
  const double lambda_m = glm::length(m);
  // λ_m − λ_a − λ_b = −λ_a λ_b |ξ_a − ξ_b|² / (λ_m + λ_a + λ_b): no cancellation when ξ_a ≈ ξ_b.
  const glm::dvec3 d = a.axis - b.axis;
  const double denom = lambda_m + a.sharpness + b.sharpness;
  const double log_scale = denom > 0.0 ? -a.sharpness * b.sharpness * glm::dot(d, d) / denom : 0.0;
  SphericalGaussian p;
  p.axis = lambda_m > 0.0 ? m / lambda_m : a.axis;
  p.sharpness = lambda_m;
  p.amplitude = a.amplitude * b.amplitude * std::exp(log_scale);
  return p;
}

glm::dvec3 inner_product(const SphericalGaussian& a, const SphericalGaussian& b) { return integral(product(a, b)); }

SgWarpedGrid::SgWarpedGrid(const glm::dvec3& axis, double sharpness, int polar)
    : z_(axis), lambda_(sharpness), mass_(-std::expm1(-2.0 * sharpness)), polar_(polar) {
  x_ = glm::normalize(std::abs(z_.x) < 0.9 ? glm::cross(glm::dvec3(1, 0, 0), z_) : glm::cross(glm::dvec3(0, 1, 0), z_));
  y_ = glm::cross(z_, x_);
}

double SgWarpedGrid::polar_cosine(int i) const {
  const double u = (i + 0.5) / polar_;
  return std::clamp(1.0 + std::log1p(-u * mass_) / lambda_, -1.0, 1.0);
}

glm::dvec3 SgWarpedGrid::direction(double cos_t, int j) const {
  const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
  const double phi = 2.0 * kPi * (j + 0.5) / azimuthal();
  return sin_t * std::cos(phi) * x_ + sin_t * std::sin(phi) * y_ + cos_t * z_;
}

double SgWarpedGrid::cell_weight() const { return (mass_ / lambda_) * (1.0 / polar_) * (2.0 * kPi / azimuthal()); }

}  // namespace weft
