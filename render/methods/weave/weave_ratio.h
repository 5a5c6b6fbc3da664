#pragma once
// The weave layer (docs/design.md §2, "Resolved weave") on the CPU: the C++ twin of
// weave_ratio.glsl and weave_vertex_pass.frag. A close-up shows each thread where it lies; the
// layer gets there by modulating what a fabric-level method drew with
//   R(x) = Σ_k P_k · f_s M P cos θ_i / Q_k  (x's one sample, SG k as a point light of power P_k)
//        / Σ_k P_k · integrand(ξ_k, ω_o)     (the fabric-level response to the same lights),
// whose average over the repeat is 1: the layer adds the weave's detail and keeps every
// method's fabric-level accuracy and shadows. Eased to 1 by the pixel's footprint (weave_detail).
#include <span>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "core/weave_layout.h"

namespace weft {

// Footprints in threads per pixel (repeats per pixel × the layout's rows: a repeat holds `rows`
// yarns across each row band, so its finest detail is a thread, whatever the weave) where the layer
// is whole (≤ first) and where it is gone (≥ second): a thread over 4 pixels shows its yarn, one
// under a pixel is the fabric-level average. Measured in repeats instead, a five-end satin's
// floats would still be drawn at 2–3 threads a pixel, 4 samples a pixel, as moiré.
inline constexpr double kWeaveFineFootprint = 1.0 / 4.0, kWeaveCoarseFootprint = 1.0;
// The footprint in threads of a pixel covering `repeats` repeats of `layout`.
inline double weave_thread_footprint(const WeaveLayout& layout, double repeats) { return repeats * layout.rows(); }
// Below this fabric-level response the factor is 1; above the cap it is clamped.
inline constexpr double kWeaveRatioFloor = 1e-7, kWeaveRatioCap = 64.0;

// An SG of sharpness λ as a point light spreads θ_i by about 1/√λ, so θ_h = (θ_i + θ_o)/2 by
// 1/(2√λ): both sides of the factor see each lobe widened by that variance, γ² → γ² + 1/(4λ).
double weave_lobe_widening(double sharpness);
// The fabric with both lobes of both threads widened by `widen2` (radians²).
Fabric widened_fabric(Fabric fabric, double widen2);

// Per vertex (the vertex pass): the fabric-level response and each SG's Q.
struct WeaveVertexTerms {
  dvec3 fabric{0.0};
  std::vector<double> q;
};
WeaveVertexTerms weave_vertex_terms(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                                    std::span<const SphericalGaussian> sgs);

// R at tile point st from (interpolated) vertex terms; 0 in a gap.
dvec3 weave_ratio(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                  glm::dvec2 st, const WeaveVertexTerms& terms, std::span<const SphericalGaussian> sgs);

// R averaged over a pixel's footprint (tile-space derivatives dx, dy), as the layer draws it: the
// layout at four rotated-grid points; a thread whose samples lie within kWeaveArcSpread of each
// other along its float is shaded once at their mean, weighted by its share of them, one whose
// samples spread further at each of them.
inline constexpr double kWeaveArcSpread = 0.125;  // WEAVE_ARC_SPREAD in weave_ratio.glsl
// The four rotated-grid points, in units of dx and dy (the `grid` of weave_ratio.glsl).
inline constexpr glm::dvec2 kWeaveFootprintGrid[4] = {{-0.125, -0.375}, {0.375, -0.125}, {0.125, 0.375}, {-0.375, 0.125}};
dvec3 weave_ratio_filtered(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                           glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, const WeaveVertexTerms& terms,
                           std::span<const SphericalGaussian> sgs);

// How much of R a pixel shows, 1 − smoothstep(fine, coarse, footprint in threads): the rest is 1.
double weave_detail(double thread_footprint);

// The layer's factor as a pixel applies it: mix(filtered R, 1, 1 − weave_detail(footprint)), the
// footprint the longer of dx and dy in threads (weave_thread_footprint).
dvec3 weave_factor(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                   glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, std::span<const SphericalGaussian> sgs);

}  // namespace weft
