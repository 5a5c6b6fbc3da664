#include "bench/stability.h"

#include <cmath>
#include <numbers>
#include <random>

#include "bench/ladder.h"
#include "methods/thin/thin.h"
#include "reference/sg_quadrature.h"
#include "reference/thin_quadrature.h"

namespace weft::bench {

namespace {
constexpr double kPi = std::numbers::pi;

dvec3 dir(double elev_deg, double azim_deg) {
  const double e = elev_deg * kPi / 180, a = azim_deg * kPi / 180;
  return dvec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
}

// A lighting of moderate SGs all round (the kind a 10-SG fit of a room gives).
SgLighting room_sgs() {
  return {{dir(60, 20), 8.0, dvec3(3.0, 2.8, 2.5)},  {dir(25, 140), 40.0, dvec3(6.0)},
          {dir(10, 260), 3.0, dvec3(0.5, 0.6, 0.8)}, {dir(-40, 80), 1.5, dvec3(0.3)},
          {dir(80, 300), 200.0, dvec3(20.0)}};
}

// Points: the flat frame and tilted ones, views at elevations in [lo, hi] degrees.
std::vector<StressPoint> points(int count, double lo, double hi, unsigned seed, bool both_sides = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<StressPoint> p;
  for (int i = 0; i < count; ++i) {
    const dvec3 n = glm::normalize(dvec3(0.25 * (u(rng) - 0.5), 0.25 * (u(rng) - 0.5), 1.0));
    SurfaceFrame f = SurfaceFrame::from_normal_warp(n, dvec3(std::cos(i * 0.7), std::sin(i * 0.7), 0.0));
    // The view's elevation above the *shading* normal, so "89°" really is 1° from grazing.
    const double elev = (lo + (hi - lo) * u(rng)) * kPi / 180, az = 2 * kPi * u(rng);
    dvec3 wo = std::sin(elev) * f.n + std::cos(elev) * (std::cos(az) * f.u + std::sin(az) * f.v);
    if (both_sides && i % 2) wo = wo - 2.0 * glm::dot(wo, f.n) * f.n;
    p.push_back({f, glm::normalize(wo)});
  }
  return p;
}
}  // namespace

std::vector<StressCase> stress_cases(const std::filesystem::path& dir_, int n) {
  const Fabric linen = load_fabric_preset("linen_plain", dir_);
  const Fabric satin = load_fabric_preset("polyester_satin_charmeuse", dir_);
  std::vector<StressCase> cases;
  cases.push_back({"narrow_sg_1e4", "three SGs with λ = 10⁴ (≈0.8° wide), one near grazing", satin,
                   {{dir(60, 10), 1e4, dvec3(1500.0)}, {dir(30, 200), 1e4, dvec3(800.0)}, {dir(8, 100), 1e4, dvec3(800.0)}},
                   points(n, 10, 85, 1)});
  // A window: 15 SGs of λ = 2000 (1.8° to 1/e) 1.5° apart along an arc at 40° elevation, a
  // bright strip ≈ 21° long and ≈ 2° across, which no single (isotropic) SG represents.
  SgLighting window;
  for (int i = 0; i < 15; ++i) window.push_back({dir(40, -10.5 + 1.5 * i), 2000.0, dvec3(300.0, 290.0, 270.0)});
  window.push_back({dir(70, 180), 2.0, dvec3(0.2)});
  cases.push_back({"window", "a strip of 15 collinear SGs with λ = 2000 (≈ 21° × 2°) over a dim ambient", satin, window,
                   points(n, 10, 85, 8)});
  cases.push_back({"grazing_view_89", "views 85–89° from the normal", linen, room_sgs(), points(n, 1, 5, 2)});
  Fabric glossy = linen;
  for (auto& t : glossy.threads) t.gamma_s = kPi / 180.0, t.gamma_v = 2.0 * kPi / 180.0;
  cases.push_back({"gamma_s_1deg", "γ_s = 1°, γ_v = 2° on linen; sharp lights", glossy,
                   {{dir(45, 0), 500.0, dvec3(100.0)}, {dir(70, 120), 2000.0, dvec3(300.0)}}, points(n, 10, 85, 3)});
  cases.push_back({"velvet", "velvet preset: pile tilted to ±90°", load_fabric_preset("velvet", dir_), room_sgs(),
                   points(n, 5, 85, 4)});
  cases.push_back({"back_lit", "all light behind the cloth; views from both sides", linen,
                   {{dir(-50, 0), 20.0, dvec3(10.0)}, {dir(-15, 90), 200.0, dvec3(50.0)}, {dir(-80, 0), 1.0, dvec3(0.5)}},
                   points(n, 10, 85, 5, true)});
  // The sheer (polyester_voile, τ = 0.4) lit from the viewer's side, from behind (a window: what
  // shows through the layer is its scattering), and along the cloth (light and views grazing).
  const Fabric voile = load_fabric_preset("polyester_voile", dir_);
  cases.push_back({"sheer_front_lit", "voile, the room's SGs, views from the lit side", voile, room_sgs(), points(n, 10, 85, 9)});
  cases.push_back({"sheer_back_lit", "voile, a bright window behind it and a dim room in front; views from both sides", voile,
                   {{dir(-30, 0), 30.0, dvec3(40.0, 38.0, 34.0)}, {dir(-60, 150), 4.0, dvec3(3.0)}, {dir(50, 90), 2.0, dvec3(0.4)}},
                   points(n, 10, 85, 10, true)});
  cases.push_back({"sheer_grazing", "voile, SGs 3–8° from the cloth's plane on both sides, views 80–88° from the normal", voile,
                   {{dir(5, 30), 300.0, dvec3(60.0)}, {dir(-3, 200), 300.0, dvec3(60.0)}, {dir(-8, 110), 40.0, dvec3(8.0)}},
                   points(n, 2, 10, 11, true)});
  cases.push_back({"all_black", "every SG amplitude 0", linen, {{dir(50, 0), 10.0, dvec3(0.0)}, {dir(10, 90), 1.0, dvec3(0.0)}},
                   points(n, 5, 85, 6)});
  cases.push_back({"hot_texel", "one λ = 10⁴ SG of amplitude 10⁶ over a dim ambient", linen,
                   {{dir(35, 60), 1e4, dvec3(1e6)}, {dir(90, 0), 0.1, dvec3(0.01)}}, points(n, 5, 85, 7)});
  return cases;
}

std::vector<dvec3> stress_reference(const StressCase& c) {
  const ClothBsdf bsdf(c.fabric, 16);
  std::vector<dvec3> ref;
  for (const auto& p : c.points) {
    SurfaceFrame f = p.frame;
    if (glm::dot(f.n, p.wo) < 0.0) f.n = -f.n, f.v = glm::cross(f.n, f.u);
    SgQuadratureOptions opt;
    opt.tolerance = 0.01;
    opt.max_polar = 256;
    ref.push_back(integrate_sg_lighting(bsdf, f, p.wo, c.sgs, opt).radiance);
  }
  return ref;
}

StressResult run_stress(const CpuMethod& method, const StressCase& c, const std::vector<dvec3>* reference,
                        int tangent_samples) {
  const ClothBsdf bsdf(c.fabric, tangent_samples);
  const bool thin = thin_reference(method.name);
  const ThinParams thin_p = thin_params(c.fabric);
  StressResult r;
  double se = 0.0, sum_ref = 0.0;
  int values = 0;
  for (size_t i = 0; i < c.points.size(); ++i) {
    const StressPoint& p = c.points[i];
    const CpuShade s = method.shade(bsdf, p.frame, p.wo, c.sgs);
    ++r.evaluations;
    bool bad = !std::isfinite(s.alpha), neg = s.alpha < 0.0 || s.alpha > 1.0;
    for (int ch = 0; ch < 3; ++ch) {
      bad = bad || !std::isfinite(s.radiance[ch]);
      neg = neg || s.radiance[ch] < 0.0;
      if (std::isfinite(s.radiance[ch])) r.max_abs = std::max(r.max_abs, std::abs(s.radiance[ch]));
    }
    r.non_finite += bad;
    r.negative += neg;
    if (!reference || bad || i >= reference->size()) continue;
    dvec3 ref = (*reference)[i];
    if (thin) {
      SurfaceFrame f = p.frame;
      if (glm::dot(f.n, p.wo) < 0.0) f.n = -f.n;
      const double a = thin_alpha(thin_p, glm::dot(f.n, p.wo));
      ref = (1.0 - a) * ref + integrate_thin_scatter(thin_p, f.n, p.wo, c.sgs, {1e-3, 0, {}}).radiance;
    }
    for (int ch = 0; ch < 3; ++ch) {
      se += (s.radiance[ch] - ref[ch]) * (s.radiance[ch] - ref[ch]);
      sum_ref += ref[ch];
      ++values;
    }
  }
  if (reference && values > 0) {
    r.measured = true;
    r.reference_mean = sum_ref / values;
    r.relative_rmse = r.reference_mean > 0.0 ? std::sqrt(se / values) / r.reference_mean : std::sqrt(se / values);
  }
  return r;
}

}  // namespace weft::bench
