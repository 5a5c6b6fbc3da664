// mizutani's approximation (render/methods/mizutani) against the converged reference of
// docs/design.md §2 on the unoccluded swatch, where the paper says it works (SGs from broad to
// moderately sharp, views off grazing), and its stability where it does not (λ = 10⁴, 89° views).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "bake/tables/azimuthal_bake.h"
#include "bake/tables/bake_selection.h"
#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "methods/mizutani/mizutani.h"
#include "reference/sg_quadrature.h"

using namespace weft;

namespace {

const AzimuthalTable& azimuthal() {
  static const AzimuthalTable t = bake_azimuthal_table();
  return t;
}

struct Baked {
  Fabric fabric;
  BakeSettings settings;
  WeightingTables tables;
};

// Coarser direction grids than the paper's 48² keep the test short; the tangent samples are the
// paper's (seed 000 Table 1), which is what the method runs with.
const Baked& baked(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Baked>> cache;
  auto& slot = cache[name];
  if (!slot) {
    slot = std::make_unique<Baked>();
    slot->fabric = load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics");
    slot->settings.tangent_samples = paper_tangent_samples(slot->fabric);
    slot->settings.xi_resolution = slot->settings.wo_resolution = slot->settings.wi_resolution = 24;
    slot->settings.lambda_levels = 5;
    slot->tables = bake_weighting_tables(slot->fabric, slot->settings);
  }
  return *slot;
}

dvec3 mizutani_at(const Baked& b, const dvec3& wo, const SgLighting& sgs) {
  const ClothBsdf bsdf(b.fabric, b.settings.tangent_samples);
  return mizutani_radiance(bsdf, b.tables, azimuthal(), SurfaceFrame{}, wo, sgs).radiance;
}

dvec3 reference_at(const Baked& b, const dvec3& wo, const SgLighting& sgs) {
  return integrate_sg_lighting(ClothBsdf(b.fabric, 32), SurfaceFrame{}, wo, sgs).radiance;  // N_j = 32: converged (docs/design.md §2)
}

// Relative error of the RGB vector: ‖got − ref‖ / ‖ref‖.
double relative_error(const dvec3& got, const dvec3& ref) { return glm::length(got - ref) / glm::length(ref); }

const SgLighting kBroad = {{glm::normalize(dvec3(-0.3, 0.1, 0.9)), 5.0, dvec3(1.0)},
                           {glm::normalize(dvec3(0.6, -0.5, 0.5)), 20.0, dvec3(0.5, 0.4, 0.3)}};
const SgLighting kSharp = {{glm::normalize(dvec3(-0.5, 0.2, 0.8)), 200.0, dvec3(1.0)}};
const dvec3 kViews[] = {dvec3(0, 0, 1), dvec3(0.5, 0.2, 0.8), dvec3(-0.2, 0.7, 0.6), dvec3(0.9, 0.1, 0.35)};

void check_fabric(const std::string& name, const SgLighting& sgs, double bound) {
  const Baked& b = baked(name);
  double worst = 0.0;
  for (const dvec3& view : kViews) {
    const dvec3 wo = glm::normalize(view);
    const dvec3 ref = reference_at(b, wo, sgs);
    const dvec3 got = mizutani_at(b, wo, sgs);
    const double err = relative_error(got, ref);
    worst = std::max(worst, err);
    std::printf("%s view (%.2f, %.2f, %.2f): reference %.5f, mizutani %.5f (green), relative error %.2f%%\n",
                name.c_str(), wo.x, wo.y, wo.z, ref.g, got.g, 100 * err);
    EXPECT_LT(err, bound) << name << " at view " << wo.x << "," << wo.y << "," << wo.z;
    EXPECT_GT(err, 0.0);  // an approximation, not the model itself
  }
  std::printf("%s: worst relative error %.2f%% (bound %.0f%%)\n", name.c_str(), 100 * worst, 100 * bound);
}

}  // namespace

TEST(MizutaniSwatch, SegmentMomentsMatchQuadrature) {
  // The closed-form pieces of the θ_i integral against a fine midpoint rule.
  for (double sigma : {0.02, 0.3, 2.0, 50.0}) {
    for (double mu : {-1.2, 0.1, 0.9}) {
      const double a = -0.4, b = 0.3;
      const SegmentMoments m = gaussian_segment_moments(a, b, mu, sigma);
      double q0 = 0.0, q1 = 0.0;
      const int n = 200000;
      for (int i = 0; i < n; ++i) {
        const double x = a + (i + 0.5) * (b - a) / n, g = std::exp(-(x - mu) * (x - mu) / (sigma * sigma));
        q0 += g * (b - a) / n;
        q1 += (x - a) * g * (b - a) / n;
      }
      EXPECT_NEAR(m.m0, q0, 1e-7 * (b - a) + 1e-6 * q0) << sigma << " " << mu;
      EXPECT_NEAR(m.m1, q1, 1e-7 * (b - a) + 1e-6 * q1) << sigma << " " << mu;
    }
  }
}

// The shading factor alone (Schlick, circular lobes, T_m table, 6-segment θ integral) against a
// midpoint rule over the same half-space, so its error is told apart from the W tables'.
MizutaniShading shading_by_quadrature(const ThreadParams& p, const ThreadFrame& f, const dvec3& wo,
                                      const SphericalGaussian& g) {
  const int n = 720;
  const double h = M_PI / n;
  const FiberAngles o = fiber_angles(f, wo);
  MizutaniShading q;
  for (int a = 0; a < n; ++a) {
    const double theta = -M_PI / 2 + (a + 0.5) * h;
    for (int b = 0; b < n; ++b) {
      const double phi = -M_PI / 2 + (b + 0.5) * h;
      const dvec3 wi = std::sin(theta) * f.t + std::cos(theta) * (std::cos(phi) * f.n_prime + std::sin(phi) * f.b);
      const FiberAngles in = fiber_angles(f, wi);
      const double cos_d = std::cos(0.5 * (in.theta - o.theta));
      const double weight = g(wi).g * std::cos(theta) * std::cos(theta) * h * h / (cos_d * cos_d);
      q.surface += surface_scattering(p, in, o) * weight;
      q.volume += volume_scattering(p, in, o).g / p.albedo.g * weight;
    }
  }
  return q;
}

TEST(MizutaniShading, MatchesQuadratureForBroadLights) {
  // The method's own approximations, per lobe, at a few frames, views and lights (λ ≤ 50).
  double worst_s = 0.0, worst_v = 0.0;
  for (const char* name : {"linen_plain", "polyester_satin_charmeuse"}) {
    const Fabric fabric = load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics");
    for (int j = 0; j < 2; ++j) {
      const ThreadParams& p = fabric.threads[j];
      const ThreadFrame f = thread_frame(SurfaceFrame{}, j, 0.3 * (1 - 2 * j));
      for (const dvec3 view : {dvec3(0.2, 0.1, 1.0), dvec3(0.6, -0.3, 0.7)})
        for (const dvec3 axis : {dvec3(-0.3, 0.2, 0.9), dvec3(0.5, 0.5, 0.6)})
          for (double lambda : {5.0, 50.0}) {
            const dvec3 wo = glm::normalize(view);
            const SphericalGaussian g{glm::normalize(axis), lambda, dvec3(1.0)};
            const MizutaniShading got = mizutani_shading(p, f, wo, g, azimuthal());
            const MizutaniShading ref = shading_by_quadrature(p, f, wo, g);
            const double es = std::abs(got.surface - ref.surface) / ref.surface;
            const double ev = std::abs(got.volume - ref.volume) / ref.volume;
            std::printf("%s thread %d λ %4.0f: surface %.4g vs %.4g (%.1f%%), volume %.4g vs %.4g (%.1f%%)\n", name,
                        j + 1, lambda, got.surface, ref.surface, 100 * es, got.volume, ref.volume, 100 * ev);
            // Relative error only where the lobe is lit (1e-3 is ~2 % of its peak here): far from
            // the light the surface lobe's value is ~0 and its relative error meaningless.
            if (ref.surface > 1e-3) worst_s = std::max(worst_s, es);
            worst_v = std::max(worst_v, ev);
          }
    }
  }
  std::printf("shading factor: worst surface %.1f%% (where lit), worst volume %.1f%%\n", 100 * worst_s, 100 * worst_v);
  // Measured 20.6 % and 11.5 %: the 6-segment θ integral and the g^c → g steps (the paper's own
  // settings) dominate; Schlick and the T_m table add < 1 %.
  EXPECT_LT(worst_s, 0.25);
  EXPECT_LT(worst_v, 0.15);
}

// Bounds from measurement (2-core VM): linen 2–8.5 % (broad), 0.7–4.9 % (λ = 200); silk 8.7–18 %,
// satin 10.7–17.9 %, both darker than the reference: their glossy threads lean on the surface
// lobe, where the 6-segment θ integral loses most (MizutaniShading above).
TEST(MizutaniSwatch, LinenBroadLights) { check_fabric("linen_plain", kBroad, 0.10); }
TEST(MizutaniSwatch, SilkBroadLights) { check_fabric("silk_crepe_de_chine", kBroad, 0.20); }
TEST(MizutaniSwatch, SatinBroadLights) { check_fabric("polyester_satin_charmeuse", kBroad, 0.20); }
TEST(MizutaniSwatch, LinenSharpLight) { check_fabric("linen_plain", kSharp, 0.06); }

TEST(MizutaniSwatch, FiniteAndNonNegativeAtStressInputs) {
  // Past the method's assumptions (λ up to 10⁴, views to 89°, lights at the horizon and below):
  // no accuracy claim, but never NaN, Inf or negative.
  for (const char* name : {"linen_plain", "polyester_satin_charmeuse"}) {
    const Baked& b = baked(name);
    for (double lambda : {0.01, 1.0, 1e3, 1e4})
      for (double view_deg : {0.0, 60.0, 85.0, 89.0})
        for (double light_deg : {0.0, 45.0, 89.0, 95.0})
          for (double azimuth : {0.0, 1.3, 3.1}) {
            const double v = view_deg * M_PI / 180, l = light_deg * M_PI / 180;
            const dvec3 wo(std::sin(v), 0.0, std::cos(v));
            const SgLighting sgs = {
                {dvec3(std::sin(l) * std::cos(azimuth), std::sin(l) * std::sin(azimuth), std::cos(l)), lambda,
                 dvec3(1.0)}};
            const dvec3 r = mizutani_at(b, wo, sgs);
            for (int c = 0; c < 3; ++c) {
              ASSERT_TRUE(std::isfinite(r[c])) << name << " λ " << lambda << " view " << view_deg << " light "
                                               << light_deg << " azimuth " << azimuth;
              ASSERT_GE(r[c], 0.0) << name << " λ " << lambda << " view " << view_deg << " light " << light_deg;
            }
          }
  }
}
