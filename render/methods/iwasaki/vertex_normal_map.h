#pragma once
// A normal map on the per-vertex rungs (iwasaki_vertex*): the C++ twin of vertex_normal_map.glsl.
// The vertex passes shade the surface's own frame; per pixel each SG's split (surface, warp volume,
// weft volume) is multiplied by
//   r_k = R_k(frame the map turns) / R_k(surface's frame),
//   R_k(n, u) = E(λ_k, ξ_k·n) / (n·ω*) · split of the integrand under a point light at ω*,
// ω* the axis ξ_k lifted to n·ω ≥ sg_effective_cosine(λ_k, ξ_k·n) (lift_to_cosine), E the SG's
// clamped-cosine integral, each lobe widened by the SG's spread (weave_lobe_widening, as the weave
// layer's ratio): a narrow lobe above the horizon is a point light at its axis, a lobe low, broad
// or below the horizon lights from above its axis, and one the bump tilts towards the horizon fades
// with its cosine-weighted share rather than stepping to zero (a point light at the axis alone
// steps where a lobe crosses the turned horizon). Part by part, so the knobs' albedos and a
// texture's texels apply after it as before, and each SG keeps the visibility the rung gave it.
// The model's r for the two SGs that light the pixel most, the clamped cosine's for the others
// (normal_map_ratios). The broad lobes (λ < kBroadLobeSharpness), smooth in the normal,
// keep the surface's frame on every per-vertex rung, as the per-pixel quadrature rungs keep them.
// The ratio's model takes at most kNormalMapRatioSamples tangent samples per thread (the bake's
// own, 3 by default, when fewer): a ratio of the same model, whose sampling error largely cancels,
// so a bake with many samples does not multiply the per-pixel cost.
#include <span>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "methods/iwasaki/iwasaki.h"

namespace weft {

// Each part's ratio is (bumped + bias)/(surface + bias), at most the cap: 1 where neither frame
// responds, continuous where a grazing lobe's responses are tiny. NORMAL_MAP_RATIO_BIAS and _CAP
// in the GLSL. The bias is far below a lit part's response (0.01–10).
inline constexpr double kNormalMapRatioBias = 1e-4, kNormalMapRatioCap = 16.0;
// A tangent-space normal whose x and y are both below this is flat: no ratio, exactly the unmapped
// image (8-bit flat codes read within float rounding of 0). NORMAL_MAP_FLAT_TILT in the GLSL.
inline constexpr double kNormalMapFlatTilt = 1e-4;
// Tangent samples per thread of the ratio's model.
inline constexpr int kNormalMapRatioSamples = 8;

// The model the ratio evaluates: the fabric at min(its samples, kNormalMapRatioSamples) per thread.
ClothBsdf normal_map_ratio_bsdf(const ClothBsdf& bsdf);

bool normal_map_tilts(const dvec3& t);

// R_k of SG g in `frame` (lobes widened by weave_lobe_widening(λ)) as (surface, warp, weft) parts.
dvec3 normal_map_lobe_response(const ClothBsdf& bsdf, const SurfaceFrame& frame, const SphericalGaussian& g,
                               const dvec3& wo);
// r_k of SG g: per part (bumped + bias)/(surface + bias), at most the cap.
dvec3 normal_map_lobe_ratio(const ClothBsdf& bsdf, const SurfaceFrame& surface, const SurfaceFrame& bumped,
                            const SphericalGaussian& g, const dvec3& wo);

// The cheap ratio of the SGs beyond the two that light a pixel most: E(λ, ξ·n_b)/E(λ, ξ·n) with
// E the clamped-cosine integral, on every part, biased by kNormalMapRatioBias·E(λ, 1), capped.
dvec3 normal_map_cosine_ratio(const dvec3& n, const dvec3& bumped_n, const SphericalGaussian& g);

// Every SG's r at a pixel whose (eye-facing) frame is `surface` and whose map reads the unit
// tangent-space normal t, `light[k]` SG k's light there (the sum of its RGB): (1, 1, 1) for a
// broad lobe (λ < kBroadLobeSharpness, or a quadrature's broad_slots[k] ≥ 0) and where t is flat;
// normal_map_lobe_ratio for the two other SGs of most light (the first of equals),
// normal_map_cosine_ratio for the rest. The cost per pixel is then about two SGs' model whatever
// the SG count; the SGs that light a pixel little are the ones a cosine stands for.
std::vector<dvec3> normal_map_ratios(const ClothBsdf& bsdf, const SurfaceFrame& surface, const dvec3& t,
                                     const dvec3& wo, std::span<const SphericalGaussian> sgs,
                                     std::span<const int> broad_slots, std::span<const double> light);

// The per-vertex rungs' pixel with a normal map (iwasaki_vertex.frag): the arguments of the tinted
// facet_interpolated_radiance (iwasaki.h), the pixel's eye-facing frame (its normal the shading
// normal), ω_o, and the map's tangent-space normal t there; each SG's light at the pixel chooses
// its ratio (normal_map_ratios). `bsdf`: normal_map_ratio_bsdf of the fabric's.
dvec3 normal_mapped_facet_radiance(const ClothBsdf& bsdf, std::span<const SphericalGaussian> sgs,
                                   std::span<const int> broad_slots,
                                   const std::array<std::span<const IwasakiTerms>, 3>& vertex_sgs, const dvec3& bary,
                                   const SurfaceFrame& surface, const dvec3& facet_normal,
                                   const std::array<dvec3, 2>& tint, const dvec3& t, const dvec3& wo);

}  // namespace weft
