#pragma once
// The weave layer (docs/design.md §2, "Resolved weave") on the CPU: the C++ twin of
// weave_ratio.glsl. A close-up shows each thread where it lies; the
// layer gets there by modulating what a fabric-level method drew with
//   R(x) = Σ_k V_k P_k · f_s M P cos θ_i / Q_k  (x's one sample, SG k as a point light of power P_k:
//        / Σ_k V_k P_k · integrand(ξ_k, ω_o)      its part above the horizon, horizon_light; V_k the
//                                                 share of it the object's geometry leaves open)
//                                                 (the fabric-level response to the same lights at x),
// whose average over the repeat is 1: the layer adds the weave's detail and keeps every
// method's fabric-level accuracy and shadows. The layer's lights are the lighting's SGs with the
// broad lobes split (methods/weave/weave_lights.h): a shadowed light shades no thread, and a
// broad lobe lights each thread from many directions. Eased to 1 by the pixel's footprint (weave_detail).
#include <span>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "core/weave_coverage.h"
#include "core/weave_layout.h"

namespace weft {

// Footprints in threads per pixel (repeats per pixel × the layout's rows: a repeat holds `rows`
// yarns across each row band, so its finest detail is a thread, whatever the weave) where the layer
// is whole (≤ first) and where it is gone (≥ second). The box-filtered layout holds a pixel of up to
// two threads (weave_coverage's floats), and a pixel of a thread or two is still far from the
// repeat's average: fading out from half a thread a pixel, a grazing satin close-up's far part was
// 22 % off the resolved reference, against 7.5 % from here. Measured in repeats instead, a five-end
// satin's floats would still be drawn at 5–10 threads a pixel.
inline constexpr double kWeaveFineFootprint = 1.0 / 2.0, kWeaveCoarseFootprint = 2.0;
// The footprint in threads of a pixel covering `repeats` repeats of `layout`.
inline double weave_thread_footprint(const WeaveLayout& layout, double repeats) { return repeats * layout.rows(); }
// Below this fabric-level response the factor is 1; above the cap it is clamped.
inline constexpr double kWeaveRatioFloor = 1e-7, kWeaveRatioCap = 64.0;

// An SG of sharpness λ as a point light spreads θ_i by about 1/√λ, so θ_h = (θ_i + θ_o)/2 by
// 1/(2√λ): both sides of the factor see each lobe widened by that variance, γ² → γ² + 1/(4λ).
double weave_lobe_widening(double sharpness);
// The fabric with both lobes of both threads widened by `widen2` (radians²).
Fabric widened_fabric(Fabric fabric, double widen2);

// An SG as a point light seen from a surface of normal n: the part of it above the surface's horizon,
// at that part's mean elevation. Across the horizon the SG is a Gaussian in elevation e of σ = 1/√λ
// about its axis's e_0; the part above has the share F = Φ(e_0/σ) of its power and the mean
// ē = e_0 + σ·φ(e_0/σ)/F. A sharp light just above the horizon taken whole at its axis would light
// every thread at grazing incidence with all its power; half of it lies below the surface.
struct HorizonLight {
  dvec3 axis{0.0, 0.0, 1.0};  // unit, at elevation ē (the SG's own axis where the horizon is far)
  double share = 0.0;         // F
};
HorizonLight horizon_light(const SphericalGaussian& g, const dvec3& n);

// The tangent samples per thread of a pixel's fabric-level terms: each sample's lobes are widened
// by the tilts of the arc it stands for (as seed 000's samples are, iwasaki.cpp's
// sample_lobe_width), so a few stand for the whole float, satin's 2.5° lobe included.
inline constexpr int kWeavePixelSamples = 16;

// A pixel's fabric-level terms: its response to the SGs as point lights (horizon_light: F_k·P_k
// along ξ'_k), Σ_k V_k F_k P_k·integrand(ξ'_k, ω_o) with each lobe widened by the SG's spread and
// each sample's by its arc's tilts, each light's Q_k, and its weight V_k/Q_k (0 where Q_k is below
// kQFloor or the light below the horizon): what the resolved response multiplies each light by.
// Per pixel, not per vertex: up close a triangle spans tens of degrees of view, and the sharp lobes
// of an interpolated response miss the pixel's own (the factor's mean over a repeat was off by
// tens of per cent on a 16×16 swatch).
struct WeaveTerms {
  dvec3 fabric{0.0};
  std::vector<double> q, weight;
};
// `bsdf` with the samples the caller wants (the layer: kWeavePixelSamples per thread);
// `visibility`: V_k per SG (empty: all 1).
WeaveTerms weave_terms(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                       std::span<const double> visibility = {});

// R at tile point st; 0 in a gap.
dvec3 weave_ratio(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                  glm::dvec2 st, const WeaveTerms& terms, std::span<const SphericalGaussian> sgs);

// Σ_k P_k f_s M P cos θ_i · V_k/Q_k of thread `thread`'s sample at `arc` along its float, its lobes
// widened by `tilt_spread` (RMS, radians) besides each light's own spread: R's numerator at one
// point of one float (each light taken as its horizon_light at frame.n).
dvec3 weave_resolved_response(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, int thread, double arc,
                              double tilt_spread, const WeaveTerms& terms, std::span<const SphericalGaussian> sgs);
// resolved / fabric per channel: 1 where the fabric-level response is below kWeaveRatioFloor,
// at most kWeaveRatioCap.
dvec3 weave_ratio_of(const dvec3& resolved, const dvec3& fabric);

// R over a pixel's footprint (tile-space derivatives dx, dy), as the layer draws it: the layout
// box-filtered over the footprint (core/weave_coverage.h), each of its largest floats shaded
// where it lies (weave_float_response), weighted by its share of the pixel (piece_weight). The
// layer over per-pixel terms; over per-vertex terms it reads the floats' shading off a table
// (methods/weave/weave_float_table.h).
dvec3 weave_ratio_filtered(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                           glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, const WeaveTerms& terms,
                           std::span<const SphericalGaussian> sgs);
// Σ_k P_k f_s M P cos θ_i · V_k/Q_k of piece i of coverage c, averaged over the piece's arc range:
// stretch by stretch between the curve's jumps (zero-length segments), each by three-point
// Gauss–Legendre, every node weighted by the footprint's density there and its lobes widened by
// the tilts of its part of the stretch (at the middle arc alone, widened by the footprint's
// tilts, where the range is a point). One shading at the middle cannot hold a float that turns
// within the pixel: a satin's back turns 30° there, a velvet's pile jumps from −55° to 55° along
// its float (its close-up 61 % off the resolved reference with one arc;
// docs/bench/weave/README.md). `lights`: each SG's horizon_light at frame.n.
dvec3 weave_float_response(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo, const WeaveCoverage& c, int i,
                           const WeaveTerms& terms, std::span<const SphericalGaussian> sgs, std::span<const HorizonLight> lights);
// The RMS tilt (radians) of thread j's float over an arc spread `arc_spread` (RMS) about `arc`: the
// curve's slope there times the spread, the slope the gentler of the two sides' within √3 spreads,
// so that a jump of the curve (velvet's weft) does not count as a spread of tilts.
double weave_tilt_spread(const Fabric& fabric, int thread, double arc, double arc_spread);

// How much of R a pixel shows, 1 − smoothstep(fine, coarse, footprint in threads): the rest is 1.
double weave_detail(double thread_footprint);

// The layer's factor as a pixel applies it: mix(filtered R, 1, 1 − weave_detail(footprint)), the
// footprint the longer of dx and dy in threads (weave_thread_footprint). `sgs`: the layer's lights
// (weave_lights); `visibility`: V_k per light at the point (empty: all 1).
dvec3 weave_factor(const ClothBsdf& bsdf, const WeaveLayout& layout, const SurfaceFrame& frame, const dvec3& wo,
                   glm::dvec2 st, glm::dvec2 dx, glm::dvec2 dy, std::span<const SphericalGaussian> sgs,
                   std::span<const double> visibility = {});

}  // namespace weft
