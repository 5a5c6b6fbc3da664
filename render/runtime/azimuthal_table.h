#pragma once
// The azimuthal table for the shadow-free `mizutani` method (seed 001 Eq. 14):
//
//   T_m(φ_o, φ_k, σ') = ∫_{−π/2}^{π/2} g^c(φ_i; φ_k, σ') · cos^m((φ_i − φ_o)/2) dφ_i,
//   g^c(x; μ, σ') = exp(2(cos(x − μ) − 1)/σ'²) = exp(λ'(cos(x − μ) − 1)),  λ' = 2/σ'².
//
// φ_i is the azimuth of ω_i around the tangent sample (φ = atan2(ω·b, ω·n'), docs/design.md §2);
// the range ±π/2 is where the masking term's max(cos φ_i, 0) is non-zero. The paper expands
// Schlick's F_r = F_0 + (1 − F_0)(1 − cosθ_d·cos(φ_d/2))⁵ as Σ_{l=0..5} C_l(θ_d) cos^l(φ_d/2),
// and the surface lobe carries one more cos(φ_d/2): the paper's T_l is T_{m = l+1}. The volume
// lobe has no cos(φ_d/2) of its own but F = (1 − F_r)², a polynomial of degree 10 in
// cos(φ_d/2), so this table holds every power m = 0..10 and both lobes read from it.
//
// Storage: T_m / Z(λ') with Z(λ') = ∫_{−π}^{π} g^c = 2π·e^{−λ'}·I_0(λ'), which lies in [0, 1]
// and varies far less with λ' than T itself; value() multiplies Z back. Axes: φ_o nodes over
// [−π/2, π/2], φ_k nodes over [−π, π], λ' nodes uniform in log(1 + λ') over [0, lambda_max];
// lookups are trilinear and clamp to the axes (φ_k is wrapped to (−π, π] first); past lambda_max
// the ratio is held at the last node while Z(λ') is exact. The table is computed offline
// (render/bake/tables/azimuthal_bake.h); this is what the runtime reads.
#include <cstddef>
#include <vector>

namespace weft {

struct AzimuthalTableSettings {
  int phi_o_nodes = 33;
  int phi_k_nodes = 65;
  int lambda_nodes = 33;
  int max_power = 10;
  double lambda_max = 2048.0;  // λ' = λ·cosθ_i·cosθ_k never exceeds the sharpest SG's λ
  int quadrature_points = 2048;
};

struct AzimuthalTable {
  AzimuthalTableSettings settings;
  std::vector<float> ratio;  // T_m / Z, index ((m·L + lambda)·K + phi_k)·O + phi_o

  // T_m(φ_o, φ_k, λ'), interpolated.
  double value(int power, double phi_o, double phi_k, double lambda_prime) const;
  // Node coordinates, for tests and the bundle's documentation.
  double phi_o_node(int i) const;
  double phi_k_node(int i) const;
  double lambda_node(int i) const;
  double node_ratio(int power, int lambda, int phi_k, int phi_o) const;
  std::size_t bytes() const { return ratio.size() * sizeof(float); }
};

// Z(λ') = ∫_{−π}^{π} exp(λ'(cos x − 1)) dx = 2π·e^{−λ'}·I_0(λ'), stable for any λ' ≥ 0.
double circular_gaussian_full_integral(double lambda_prime);

}  // namespace weft
