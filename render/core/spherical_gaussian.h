#pragma once
// Spherical Gaussians (docs/design.md §3): G(ω) = μ·exp(λ(ω·ξ − 1)), μ RGB radiance, λ = 2/σ²
// (σ: sg_bandwidth). An environment is a small set of them (10 by default).
//
// Integrals of SGs used by the lighting fit, the baker and the runtime methods. Sharpness λ ≥ 0
// everywhere (λ = 0 is the constant function μ); axes and normals are unit vectors.
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace weft {

struct SphericalGaussian {
  glm::dvec3 axis{0, 0, 1};       // ξ, unit length
  double sharpness = 1.0;         // λ
  glm::dvec3 amplitude{1.0};      // μ (RGB)

  // Value in direction w (unit).
  glm::dvec3 operator()(const glm::dvec3& w) const {
    return amplitude * std::exp(sharpness * (glm::dot(w, axis) - 1.0));
  }
};

using SgLighting = std::vector<SphericalGaussian>;

// Radiance of a set of SGs in direction w.
glm::dvec3 evaluate(std::span<const SphericalGaussian> sgs, const glm::dvec3& w);

// σ of seed 000 Eq. 1 from λ and back: λ = 2/σ².
double sg_bandwidth(double sharpness);
double sg_sharpness(double bandwidth);

// ---- Unit-amplitude integrals (scalars: the RGB versions below multiply by μ) ----

// ∫_{S²} exp(λ(ω·ξ−1)) dω = 2π(1 − e^{−2λ})/λ, exact (4π at λ = 0).
double sg_sphere_integral(double sharpness);

// ∫_{ω·n>0} exp(λ(ω·ξ−1)) dω with c = ξ·n. No elementary closed form exists for general c; this
// is Tokuyoshi's (2022, "Accurate Diffuse Lighting from Spherical Gaussian Lights") fit: a lerp
// between the exact integrals for c = −1 and c = +1, 2π(1−e^{−λ})/λ·(e^{−λ}, 1), with factor
// ½ + ½·erf(t·c)/erf(t), t = λ·√((λ/2 + A)/((λ + B)λ + C)). Exact at c ∈ {−1, 0, 1} and as
// λ → 0. Measured error (tests/core/sg_math_test.cpp, 16 λ in [0.01, 10⁴], c every 2.25°): at most
// 0.44 % of the whole-sphere integral (worst at λ ≈ 10, c ≈ 0.59), and at most 2.0 % of the value
// itself wherever that is at least 10 % of the whole-sphere integral (worst at λ ≈ 5, c ≈ −0.59).
double sg_hemisphere_integral(double sharpness, double cos_axis_normal);

// The share of an SG's sphere integral above the plane ω·n = 0: sg_hemisphere_integral over
// sg_sphere_integral, = (e^{−λ} + (1 − e^{−λ})·factor)/(1 + e^{−λ}) with the same fitted factor.
// 1/(1 + e^{λ}) at c = −1, ½ at c = 0, 1/(1 + e^{−λ}) at c = 1; → ½erfc(−c√(λ/2)) for sharp lobes.
double sg_hemisphere_fraction(double sharpness, double cos_axis_normal);
// sg_hemisphere_fraction's factors that depend on λ alone: the lerp's steepness t, 1/erf(t) (0
// where t is so small the lerp is linear) and e^{−λ}. A shader that evaluates the fraction of one
// lobe at many points takes them once per lobe (iwasaki_vertex.frag's u_sg_hemisphere_terms).
struct SgHemisphereTerms {
  double steepness = 0.0, inverse_erf = 0.0, exp_minus_lambda = 1.0;
};
SgHemisphereTerms sg_hemisphere_terms(double sharpness);
double sg_hemisphere_fraction(const SgHemisphereTerms& terms, double cos_axis_normal);

// ∫_{S²} exp(λ(ω·ξ−1)) max(ω·n, 0) dω with c = ξ·n: the clamped-cosine (irradiance) convolution.
// Tokuyoshi et al. 2024 ("Hierarchical Light Sampling with Accurate Spherical Gaussian Lighting"):
// a lerp between the exact values at c = −1 and c = +1 with a factor built from the exact
// integral of a Gaussian times a linear ramp, its steepness t(λ) a fitted rational function.
// Exact at c = ±1 and as λ → 0. Measured error (same sweep as above): at most 0.16 % of the
// c = +1 value (worst at λ ≈ 5, c ≈ 0.68), and at most 0.72 % of the value itself wherever that is
// at least 10 % of the c = +1 value.
double sg_clamped_cosine_integral(double sharpness, double cos_axis_normal);

// ---- RGB versions ----

// ∫_{S²} G(ω) dω.
glm::dvec3 integral(const SphericalGaussian& g);
// ∫_{ω·n>0} G(ω) dω (approximation above).
glm::dvec3 hemisphere_integral(const SphericalGaussian& g, const glm::dvec3& n);
// ∫_{S²} G(ω) max(ω·n, 0) dω: irradiance at a normal n from G (approximation above).
glm::dvec3 irradiance(const SphericalGaussian& g, const glm::dvec3& n);

// The part of G above the plane ω·n = 0 as one SG whose axis is not below it: G itself when
// ξ·n ≥ 0; otherwise an SG on the horizon direction e nearest the axis (ξ = c·n + s·e, c < 0).
// - A broad lobe (λ ≤ 4) shows a wide cap: the SG on e whose sharpness λ·s is G's own along the
//   horizon (G restricted to the horizon is μe^{λ(s−1)}·e^{λs(ω·e−1)}), and whose amplitude keeps
//   G's clamped-cosine integral at n: μ' = μ·C(λ, c)/C(λ·s, 0), C = sg_clamped_cosine_integral.
//   At the nadir e is any horizon direction and λ' the floor: the visible part is a ring, nearly
//   uniform for the broad ground lobes a sky's fit holds.
// - A sharp lobe (λ ≥ 16, a sun just below the horizon) shows a thin sliver that hugs the horizon
//   (its height decays as e^{λch}, faster than the re-aimed SG's): the SG on e that keeps both
//   G's power above the plane, H(λ, c) (sg_hemisphere_integral), and its mean cosine there, C/H:
//   λ' from horizon_sharpness_for_mean_cosine, μ' = μ·H(λ, c)/H(λ', 0). The broad rule gave a
//   λ = 1000 sun 2° below the horizon 38 % of its light short (docs/research/iwasaki.md).
// - In between, λ' and μ' are blended geometrically (horizon_sliver_weight).
// λ' ≥ `min_sharpness`.
SphericalGaussian above_horizon(const SphericalGaussian& g, const glm::dvec3& n, double min_sharpness);

// Where above_horizon goes from the broad lobe's rule (weight 0) to the sharp one's (weight 1):
// linear in log λ between these sharpnesses.
inline constexpr double kHorizonSliverFrom = 4.0, kHorizonSliverTo = 16.0;
double horizon_sliver_weight(double sharpness);

// The sharpness λ' ≥ `min_sharpness` of an SG on the horizon whose mean cosine to the normal over
// the hemisphere, C(λ', 0)/H(λ', 0), equals `mean_cosine` (it falls as λ' grows): bisection in
// log λ' over kHorizonSharpnessLogRange, kHorizonSharpnessSteps steps (iwasaki.glsl does the same).
inline constexpr double kHorizonSharpnessLogRange = 12.0;
inline constexpr int kHorizonSharpnessSteps = 16;
double horizon_sharpness_for_mean_cosine(double mean_cosine, double min_sharpness);

// The SG-warped grid: an n × 2n midpoint grid in (u, φ) in the SG's own frame (axis ξ, x and y
// from sg_grid_basis), u the SG's cumulative polar mass: cos θ = 1 + ln(1 − u(1 − e^{−2λ}))/λ makes
// exp(λ(cos θ − 1)) dcos θ = (1 − e^{−2λ})/λ du, so every cell holds the same share of the SG,
// (1 − e^{−2λ})/λ · 2π/(2n²) = ∫exp(λ(ω·ξ − 1))dω/(2n²), and a sum over cells weights only the
// integrand. The reference's SG quadrature and the broad-lobe quadrature of the runtime
// (methods/iwasaki/broad_lobe_quadrature.h; GLSL in shaders/sg_lighting.glsl) use it.
class SgWarpedGrid {
public:
  SgWarpedGrid(const glm::dvec3& axis, double sharpness, int polar);
  int polar() const { return polar_; }              // n: rows of equal polar mass
  int azimuthal() const { return 2 * polar_; }      // 2n: columns of equal φ
  double polar_cosine(int i) const;                 // cos θ of row i's centre
  // Cell (i, j)'s centre, a unit vector (i < n, j < 2n); `cos_theta` = polar_cosine(i).
  glm::dvec3 direction(int i, int j) const { return direction(polar_cosine(i), j); }
  glm::dvec3 direction(double cos_theta, int j) const;
  // ∫exp(λ(ω·ξ − 1))dω over one cell (unit amplitude).
  double cell_weight() const;

private:
  glm::dvec3 x_, y_, z_;
  double lambda_, mass_;
  int polar_;
};

// The product of two SGs is an SG, exactly: λ_m ξ_m = λ_a ξ_a + λ_b ξ_b, λ_m = |λ_a ξ_a + λ_b ξ_b|,
// μ_m = μ_a μ_b exp(λ_m − λ_a − λ_b) (amplitudes multiply per channel). Where the lobes cancel
// (λ_m = 0) the product is the constant μ_m and the axis is a's.
SphericalGaussian product(const SphericalGaussian& a, const SphericalGaussian& b);

// ∫_{S²} G_a(ω) G_b(ω) dω = the integral of product(a, b), exact.
glm::dvec3 inner_product(const SphericalGaussian& a, const SphericalGaussian& b);

}  // namespace weft
