// iwasaki's approximation (render/methods/iwasaki) against the converged reference on the
// unoccluded swatch: the factorisation of Eq. 9, the circular-Gaussian lobes of Eq. 11–13 and
// the SVD tables together stay within a few percent where the paper says they work.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "methods/iwasaki/iwasaki.h"
#include "reference/sg_quadrature.h"
#include "support/sky_direction.h"

using namespace weft;
using test::at_elevation;

namespace {

struct LinenSwatch {
  Fabric linen = load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  BakeSettings settings = [] {
    BakeSettings s;  // coarser than the paper's 48² grids to keep the test short
    s.tangent_samples = {3, 3};
    s.xi_resolution = s.wo_resolution = s.wi_resolution = 32;
    s.lambda_levels = 8;  // ×4 apart over the default λ range
    return s;
  }();
  WeightingTables tables = bake_weighting_tables(linen, settings);
};
const LinenSwatch& swatch() {
  static const LinenSwatch s;
  return s;
}

// iwasaki against the converged reference at each view on the flat swatch; each relative
// error (RGB vector) must be > 0 (an approximation, not the model itself) and < bound.
void expect_close(const SgLighting& sgs, std::initializer_list<dvec3> views, double bound) {
  const LinenSwatch& s = swatch();
  const ClothBsdf approx(s.linen, s.settings.tangent_samples), exact(s.linen, 64);
  for (const dvec3& view : views) {
    const dvec3 wo = glm::normalize(view);
    const dvec3 ref = integrate_sg_lighting(exact, SurfaceFrame{}, wo, sgs).radiance;
    const dvec3 got = iwasaki_radiance(approx, s.tables, SurfaceFrame{}, wo, sgs).radiance;
    const double err = glm::length(got - ref) / glm::length(ref);
    std::printf("view (%.2f, %.2f, %.2f): reference %.5f, iwasaki %.5f (green), relative error %.2f%%\n", wo.x, wo.y,
                wo.z, ref.g, got.g, 100 * err);
    EXPECT_LT(err, bound);
    EXPECT_GT(err, 0.0);
  }
}


}  // namespace

TEST(IwasakiSwatch, LinenWithinFivePercentOfReference) {
  expect_close({{glm::normalize(dvec3(-0.3, 0.1, 0.9)), 20.0, dvec3(1.0)},
                {glm::normalize(dvec3(0.6, -0.5, 0.5)), 150.0, dvec3(0.5, 0.4, 0.3)}},
               {dvec3(0, 0, 1), dvec3(0.5, 0.2, 0.8), dvec3(0.9, 0.1, 0.3)}, 0.05);
}

// Sharp lights a few degrees above and below the horizon (a studio's softboxes seen from a
// table): part of each lobe lies below the surface, where W = 0. T averages W over the part
// above, so the shading factor must stop at the horizon too (iwasaki.cpp's horizon_ratio);
// without it the tilted samples' hemispheres let the lobes' lower halves in: 47–73 % error here
// instead of 2.2–6.0 % (0.2–5.5 % on the equal-area node square of before 2026-12).
TEST(IwasakiSwatch, GrazingLightStopsAtTheHorizon) {
  expect_close({{at_elevation(100, 3), 500.0, dvec3(1.0)},
                {at_elevation(-60, 1), 300.0, dvec3(1.0)},
                {at_elevation(200, -3), 200.0, dvec3(1.0)}},
               {dvec3(0, -0.77, 0.64), dvec3(0.3, -0.6, 0.74), dvec3(-0.4, -0.2, 0.9)}, 0.08);
}

// The pillow's top seen from a low camera: views 74–84° from the normal under a studio's sharp
// lights low in the sky. W, so T, is steepest in ω_o there; the node grid's rings, dense at the
// horizon (hemisphere_grid.h), keep T's interpolation from dominating the error: 2.1–6.3 % here,
// 1.2–9.9 % on the equal-area node square.
TEST(IwasakiSwatch, GrazingViewUnderLowSharpLights) {
  expect_close({{at_elevation(30, 4), 1000.0, dvec3(1.0)},
                {at_elevation(-140, 12), 400.0, dvec3(0.8)},
                {at_elevation(95, 25), 300.0, dvec3(0.6)}},
               {at_elevation(-160, 6), at_elevation(-120, 10), at_elevation(170, 16), at_elevation(-95, 12)}, 0.08);
}

// A sky's fit holds 4–5 broad lobes (λ ≈ 1.7–2.5) and may go down to λ = 0.1 (sg_fit.h). Each
// lobe is cut once, at the surface's horizon, by the share of the SG above it (iwasaki.cpp's
// lobe_horizon_fraction; φ integrated over the whole circle), and Eq. 13's frozen σ' and cos θ
// are scaled to the SG's exact integral (separable_spread). With the sample's own hemisphere cut
// as well and the horizon linearised at the peak, λ = 2 at the horizon was 55 % too dark, λ = 1 at
// 30° 28 % (the two cuts had cancelled the frozen form's excess at the zenith: +0.3 / +1.4 %).
// What is left: the broadest lobes at the zenith (λ = 1: 7–13 %, λ = 0.5: 22–32 %), the smooth
// factors taken at the peak of a lobe that covers the hemisphere.
TEST(IwasakiSwatch, BroadSkyLobes) {
  expect_close({{dvec3(0, 0, 1), 2.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.05);
  expect_close({{at_elevation(40, 60), 2.0, dvec3(1.0)}}, {dvec3(0.3, 0.2, 0.93), dvec3(-0.2, -0.3, 0.93)}, 0.05);
  expect_close({{at_elevation(40, 30), 1.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.06);
  expect_close({{at_elevation(40, 0), 2.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.12);
  expect_close({{dvec3(0, 0, 1), 1.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.14);
}

// Broad lobes along a thread (the warp along x, the weft along y): for that thread's samples the
// SG sits near the pole θ = ±π/2, where Eq. 13's frozen form vanishes with cos θ_k. Its ratio to
// the SG's exact integral is then > 1; the model's cos²θ_l at the peak is small there too, and
// scaling by that ratio over-brightened these lobes (separable_spread is kept ≤ 1): with the ratio
// up to 4, +3 to +6 % and +8 to +12 % here; kept ≤ 1, 1.1–3.7 %.
TEST(IwasakiSwatch, BroadLobesAlongTheThreads) {
  expect_close({{at_elevation(0, 30), 2.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.08);
  expect_close({{at_elevation(90, 15), 1.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(-0.3, 0.2, 0.93)}, 0.08);
}

// A sky's ground lobes point below the surface (sky:elev=60: λ 0.28 at z = −0.98, λ 0.38 at
// z = −0.34), yet their tails above it are real light. Shaded at their peak they gave nothing (the
// horizon cut linearised at a nadir peak is 0, and the smooth factors there vanish: −100 %, −73 to
// −96 % at 20–45° below); as their part above the surface (core's above_horizon: the SG on the
// nearest horizon direction with its sharpness along the horizon and its clamped-cosine power)
// they are within a few percent.
TEST(IwasakiSwatch, LobesBelowTheHorizon) {
  expect_close({{dvec3(0, 0, -1), 0.28, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.10);
  expect_close({{at_elevation(40, -45), 0.5, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.03);
  expect_close({{at_elevation(40, -20), 1.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.05);
  expect_close({{at_elevation(40, -45), 2.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.10);
}

struct SatinSwatch {
  Fabric satin = load_fabric_preset("polyester_satin_charmeuse", WEFT_SOURCE_ASSETS "/fabrics");
  BakeSettings settings = [] {
    BakeSettings s;  // the paper's 15+1 samples (paper_tangent_samples), coarser grids
    s.tangent_samples = {15, 1};
    s.xi_resolution = s.wo_resolution = s.wi_resolution = 32;
    s.lambda_levels = 8;
    return s;
  }();
  WeightingTables tables = bake_weighting_tables(satin, settings);
};
const SatinSwatch& satin_swatch() {
  static const SatinSwatch s;
  return s;
}

// Satin's float (γ_s 2.5°) keeps of a medium lobe only a band along its specular cone, where the
// weight W differs from its mean over the whole SG that Eq. 9's T holds. T read at the surface
// lobe's peak instead of at the SG's axis (iwasaki.cpp: at fiber_direction of the peak): a λ = 19 lobe (the
// fit's ring round a sun) on and off the warp's and the weft's specular cones, −18 / +22 / +44 %
// with T at the axis. Against the model with the same 15+1 tangent samples: with a sharp light
// the samples' discrete tilts alone move satin's highlight by more than the approximation's error.
TEST(IwasakiSwatch, SatinTakesTheWeightWhereItsNarrowLobeIs) {
  const SatinSwatch& s = satin_swatch();
  const ClothBsdf bsdf(s.satin, s.settings.tangent_samples);
  struct Case {
    dvec3 axis, view;
  };
  for (const Case& c : {Case{at_elevation(90, 5), dvec3(0, 0, 1)}, Case{at_elevation(40, 5), dvec3(0.3, 0.2, 0.93)},
                        Case{at_elevation(-12.32, 20), dvec3(0.3, 0.2, 0.93)},
                        Case{at_elevation(52.91, 5), dvec3(-0.6, 0.3, 0.74)}}) {
    const SgLighting sgs = {{c.axis, 19.0, dvec3(1.0)}};
    const dvec3 wo = glm::normalize(c.view);
    const dvec3 ref = integrate_sg_lighting(bsdf, SurfaceFrame{}, wo, sgs).radiance;
    const dvec3 got = iwasaki_radiance(bsdf, s.tables, SurfaceFrame{}, wo, sgs).radiance;
    const double err = glm::length(got - ref) / glm::length(ref);
    std::printf("satin, SG (%.2f, %.2f, %.2f) λ 19, view (%.2f, %.2f, %.2f): reference %.5f, iwasaki %.5f (green), %.2f%%\n",
                c.axis.x, c.axis.y, c.axis.z, wo.x, wo.y, wo.z, ref.g, got.g, 100 * err);
    EXPECT_LT(err, 0.08);
    EXPECT_GT(err, 0.0);
  }
}

// A sun (λ = 1000, the fit's cap) on satin's float, against the model's curve converged (64
// samples per thread; 256 changes these points by < 1 %). iwasaki's 15 samples each widen their
// lobes by the tilts of the arc they stand for (iwasaki.cpp's sample_lobe_width); at their own
// tilts alone the highlight sits only where a sample is specular: −13 to +43 % over these
// azimuths (the model itself at 15 samples: the same; at the bench reference's 16: −17 to +30 %).
TEST(IwasakiSwatch, SatinSunAveragesTheFloatsTilts) {
  const SatinSwatch& s = satin_swatch();
  const ClothBsdf bsdf(s.satin, s.settings.tangent_samples), converged(s.satin, 64);
  const dvec3 wo(0, 0, 1);
  for (double azimuth : {30.0, 45.0, 50.0, 55.0, 60.0}) {
    const SgLighting sgs = {{at_elevation(azimuth, 20), 1000.0, dvec3(1.0)}};
    const dvec3 ref = integrate_sg_lighting(converged, SurfaceFrame{}, wo, sgs).radiance;
    const dvec3 got = iwasaki_radiance(bsdf, s.tables, SurfaceFrame{}, wo, sgs).radiance;
    const double err = glm::length(got - ref) / glm::length(ref);
    std::printf("satin, sun at 20° azimuth %.0f°, view +z: reference %.3e, iwasaki %.3e (green), %.2f%%\n", azimuth, ref.g,
                got.g, 100 * err);
    EXPECT_LT(err, 0.10);
    EXPECT_GT(err, 0.0);
  }
}

// A sun just below the surface's horizon (the pillow's far side under a low sun): only a thin
// sliver of the lobe is above the surface, hugging the horizon. above_horizon re-aims a sharp
// lobe so that it keeps the sliver's power and mean cosine; with the broad lobes' rule (λ·s and
// G's clamped cosine) these points were 17–38 % too dark (λ = 1000 at −0.5° and −2°), 22 % for
// λ = 300 at −2° and 11 % for λ = 100 at −2°; now within 1–8 % (docs/research/iwasaki.md).
TEST(IwasakiSwatch, SunJustBelowTheHorizon) {
  expect_close({{at_elevation(40, -0.5), 1000.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.10);
  expect_close({{at_elevation(40, -2), 1000.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.06);
  expect_close({{at_elevation(40, -2), 300.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.10);
  expect_close({{at_elevation(40, -2), 100.0, dvec3(1.0)}}, {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93)}, 0.06);
}

TEST(IwasakiSwatch, LinearInAlbedoWithoutRebake) {
  // The knobs change A without touching the tables: the volume term scales exactly with A.
  Fabric linen = load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  BakeSettings s;
  s.tangent_samples = {2, 2};
  s.xi_resolution = s.wo_resolution = s.wi_resolution = 16;
  s.lambda_levels = 3;
  const WeightingTables tables = bake_weighting_tables(linen, s);
  const SgLighting sgs = {{glm::normalize(dvec3(-0.3, 0.1, 0.9)), 20.0, dvec3(1.0)}};
  const dvec3 wo = glm::normalize(dvec3(0.5, 0.2, 0.8));
  const IwasakiTerms a = iwasaki_radiance(ClothBsdf(linen, s.tangent_samples), tables, SurfaceFrame{}, wo, sgs);
  for (auto& t : linen.threads) t.albedo *= 2.0;
  const IwasakiTerms b = iwasaki_radiance(ClothBsdf(linen, s.tangent_samples), tables, SurfaceFrame{}, wo, sgs);
  EXPECT_NEAR(b.volume.g, 2.0 * a.volume.g, 1e-12 * a.volume.g);
  EXPECT_NEAR(b.surface.g, a.surface.g, 1e-15);
  EXPECT_GT(a.surface.g, 0.0);
}

