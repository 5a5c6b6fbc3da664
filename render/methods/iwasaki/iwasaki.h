#pragma once
// The weighting-table approximation of seed 000 (Iwasaki et al. 2014, §3) of L_o at one cloth point under SGs:
//   L_o = Σ_k μ_k Σ_j (1/N_j) Σ_{t∈C_j} T_{t,λ_k}(ξ_k, ω_o) · ∫ G_k V f_s cos θ_i dω_i      (Eq. 8–10)
// with T for the longitudinal lobes read at the surface lobe's peak instead of ξ_k (SGs with
// λ ≥ 8; blended down to ξ_k at λ = 2): a narrow lobe keeps only a band of the SG (iwasaki.cpp).
// with the second factor from circular Gaussians (Eq. 11–13): the SG split into g^c(θ)·g^c(φ),
// each longitudinal lobe g^u(θ_h; γ) replaced by a circular Gaussian in θ_i and merged with
// the SG's, the smooth factors taken at the product's peak (θ_l, φ_k), and the visibility as
// the ratio H of the linearised-visibility integral (here: none, or a caller's H), and the
// surface's own horizon as the one cut of each lobe (T is the average of W above the horizon, so
// the lobes are cut there too, by lobe_horizon_fraction; φ then runs over the whole circle).
// An SG whose axis is below the surface is shaded as its part above it (above_horizon), and Eq.
// 13's frozen σ' and cos θ are scaled to the SG's exact integral (iwasaki.cpp, separable_spread).
#include <array>
#include <functional>
#include <span>

#include "runtime/sigmoid_gain_table.h"
#include "runtime/weighting_tables.h"
#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"

namespace weft {

// H(σ_l, σ'_l, d, ∂d/∂θ, ∂d/∂φ) at (θ_l, φ_k) of a tangent sample, or empty for unoccluded.
struct IwasakiVisibility {
  // Linearised visibility at direction (θ, φ) of the sample frame: d and its gradient. Called
  // once per (SG, tangent sample), with the SG's index and direction (θ_k, φ_k); each lobe's H
  // takes d carried along that plane to its own peak (θ_l, φ_k).
  std::function<void(int sg, const ThreadFrame&, double theta, double phi, double& d, double& d_dtheta, double& d_dphi)>
      sdf;
  // Eq. 14's sigmoid with the baked gains replaces the closed-form H when given (the runtime's
  // choice: the GPU reads the same table).
  const SigmoidGainTable* kappa = nullptr;
  // Instead of an SDF: the share V_k of SG k's part above the surface that no geometry blocks
  // (a baked visibility mask, iwasaki_visibility.h's SgVisibility::from_mask), multiplying the
  // SG's whole contribution; the lobes are then cut at the surface's horizon alone.
  std::function<double(int sg)> open_share;
  // The facet's (geometric) normal at a pixel, facing ω_o, or zero for none (per vertex): each SG
  // is scaled by facet_horizon_factor, the share of it the facet's plane lets through.
  dvec3 facet_normal{0.0};
};

// The visibility a point is shaded with on the side facing the eye: the bake cast from the side
// its mesh normal points to, so seen from behind (a fold's top layer, a curtain's back) the baked
// SDF and shares say nothing of the side shaded and are dropped (open; the facet's cut stays), as
// iwasaki_sg_split does.
inline IwasakiVisibility on_side_shaded(IwasakiVisibility v, bool seen_from_behind) {
  if (seen_from_behind) v.sdf = nullptr, v.open_share = nullptr, v.kappa = nullptr;
  return v;
}

struct IwasakiTerms {
  dvec3 radiance{0.0};
  dvec3 surface{0.0};  // Σ over the f_rs part
  dvec3 volume{0.0};   // Σ over the f_rv part
  // The f_rv part of each thread (volume = their sum): what a texture's texel on thread j scales
  // (radiance = surface + Σ_j tint_j·thread_volume[j]).
  std::array<dvec3, 2> thread_volume{dvec3(0.0), dvec3(0.0)};
  // The radiance with thread j's albedo times tint[j].
  dvec3 tinted(const std::array<dvec3, 2>& tint) const { return surface + tint[0] * thread_volume[0] + tint[1] * thread_volume[1]; }
};

// `bsdf` supplies the thread parameters (A, γ_s, γ_v, η, k_d: the knobs) and the tangent
// samples, which must be those the tables were baked for.
// H of the surface's own horizon (h = ω·n linearised at (θ, φ) of sample frame `tf`) for a lobe
// of widths σ_l, σ' there: the closed form of Eq. 12 for that straight boundary (iwasaki.cpp).
// Also the horizon the Lambertian floors divide out (lambert_visibility.h).
double horizon_ratio(const ThreadFrame& tf, const dvec3& n, double theta, double phi, double sigma_l, double sigma_p);
// The share of a lobe of widths σ_l, σ' at (θ, φ) of sample frame `tf` above the surface: the
// share of an SG above a plane (sg_hemisphere_fraction, exact at the poles) for the lobe's width
// along h = ω·n's gradient. Equals horizon_ratio for sharp lobes near the horizon; unlike it, it
// keeps a broad lobe's far side below the surface out, and a nadir lobe's tail above it in.
double lobe_horizon_fraction(const ThreadFrame& tf, const dvec3& n, double theta, double phi, double sigma_l,
                             double sigma_p);

// A faceted mesh with interpolated normals: the surface seen at a pixel is the triangle, whose
// plane blocks what lies below it even where the shading normal's horizon lets it through (the
// reference casts rays from the facet). The share of SG g above both planes over its share above
// the shading plane, approximated by min(1, H(λ, ξ·n_g)/H(λ, ξ·n_s)) with H the share above one
// plane (sg_hemisphere_fraction): exact when the planes coincide and, for a narrow lobe, when
// only one of them cuts it. 1 where the normals agree to 1e−4 or the facet normal is zero.
double facet_horizon_factor(const SphericalGaussian& g, const dvec3& shading_normal, const dvec3& facet_normal);

IwasakiTerms iwasaki_radiance(const ClothBsdf& bsdf, const WeightingTables& tables, const SurfaceFrame& frame,
                              const dvec3& wo, std::span<const SphericalGaussian> sgs,
                              const IwasakiVisibility* visibility = nullptr);
// SG k of `sgs` alone (the visibility called with k): what the per-vertex pass stores per (vertex, SG).
IwasakiTerms iwasaki_sg_radiance(const ClothBsdf& bsdf, const WeightingTables& tables, const SurfaceFrame& frame,
                                 const dvec3& wo, std::span<const SphericalGaussian> sgs, size_t k,
                                 const IwasakiVisibility* visibility = nullptr);

// The per-vertex rungs at a pixel (iwasaki_vertex.frag): SG k's radiance at the triangle's three
// vertices (vertex_sgs[i][k], from iwasaki_sg_radiance or a broad lobe's quadrature) blended with
// the pixel's barycentrics, times facet_horizon_factor at the interpolated shading normal and the
// triangle's normal (both facing ω_o), summed over k. An SG with broad_slots[k] ≥ 0 (the broad
// lobes' quadrature, whose mask bits hold the horizon) is blended alone; empty broad_slots: none.
dvec3 facet_interpolated_radiance(std::span<const SphericalGaussian> sgs, std::span<const int> broad_slots,
                                  const std::array<std::span<const dvec3>, 3>& vertex_sgs, const dvec3& bary,
                                  const dvec3& shading_normal, const dvec3& facet_normal);

// The same for a textured cloth (iwasaki_vertex.frag with thread_maps.glsl): per vertex and SG the
// terms (surface and each thread's volume part), blended and cut alike, each thread's part times
// its texel at the pixel, tint[j]; with a normal map, SG k's parts (surface, warp, weft) times
// normal_map_ratios[k] (methods/iwasaki/vertex_normal_map.h; empty: none).
dvec3 facet_interpolated_radiance(std::span<const SphericalGaussian> sgs, std::span<const int> broad_slots,
                                  const std::array<std::span<const IwasakiTerms>, 3>& vertex_sgs, const dvec3& bary,
                                  const dvec3& shading_normal, const dvec3& facet_normal, const std::array<dvec3, 2>& tint,
                                  std::span<const dvec3> normal_map_ratios = {});

}  // namespace weft
