#include "methods/iwasaki/iwasaki.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/circular_gaussian.h"
#include "core/fresnel.h"

namespace weft {

namespace {

// σ' of Eq. 11 at a lobe's peak, with cos θ·cos θ_k kept ≥ 1e−6: at a pole (or a peak past
// it) σ' → ∞ and σ'·[erf − erf] tends to a finite limit, but ∞·0 would give NaN.
double lobe_sigma_prime(double sigma_k, double theta, double theta_k) {
  return sigma_k / std::sqrt(std::max(std::cos(theta) * std::cos(theta_k), 1e-6));
}

// Eq. 13 freezes σ' and the measure's cos θ (dω = cos θ dθ dφ) at the lobe's peak, and counts
// the broad lobe's far sides at the peak's values. For the SG itself the exact integral is known,
// ∫G dω = 2π(1 − e^{−2λ})/λ; its ratio to the frozen form at (θ_k, σ_k), with the φ integral over
// the whole circle (circular_gaussian_circle_integral), corrects that: → 1 for sharp lobes, 0.71
// for a λ = 0.28 lobe at the zenith. Kept in [¼, 1]: it only removes the frozen form's excess.
// Near the thread's poles the frozen form vanishes with cos θ_k and the ratio grows past 1, but
// there the model's cos²θ_l is taken at the peak as well, and letting the ratio brighten those
// lobes (up to 4) leaves the pillow under skies 1–1.2 points of relative RMSE worse (docs/research/iwasaki.md).
double separable_spread(double lambda, double theta_k, double sigma_k) {
  const double frozen = gaussian_half_turn_integral(theta_k, sigma_k) *
                        circular_gaussian_circle_integral(lobe_sigma_prime(sigma_k, theta_k, theta_k)) *
                        std::max(std::cos(theta_k), 1e-3);
  return std::clamp(sg_sphere_integral(lambda) / frozen, 0.25, 1.0);
}
// The same correction for a lobe of θ-width σ_l ≤ σ_k (the SG merged with a longitudinal lobe):
// it is second order in the width, so its logarithm scales with σ_l²/σ_k².
double lobe_spread(double spread_k, double sigma_l, double sigma_k) {
  return std::pow(spread_k, (sigma_l * sigma_l) / (sigma_k * sigma_k));
}

// The linear visibility of one (SG, tangent sample): d and ∇d looked up once, at the SG's own
// direction (θ_k, φ_k), and carried to each lobe's peak along the plane they define. All lobes
// peak at φ_k and near θ_k, and V' is linear anyway (Eq. 12): one SDF lookup instead of three.
struct LinearSdf {
  bool on = false;
  double d = 0, d_dtheta = 0, d_dphi = 0, theta = 0;
};

// ∫∫ g^c(θ;θ_l,σ_l) g^c(φ;φ_k,σ'_l) V'(θ,φ) dθ dφ (Eq. 12–13), θ over [−π/2, π/2] and φ over the
// whole circle: Eq. 13's square is the tangent sample's own hemisphere, a second cut next to the
// surface's horizon (T already holds W's zeros below the sample), which for an untilted sample is
// the same plane: a lobe at the horizon was counted at ¼ instead of ½. V' is the horizon's alone
// without an SDF; with one (whose bake counts everything below the horizon as
// occluded, so its nearest boundary may be the horizon itself) the smaller of the two ratios:
// the visible set lies inside both, and a product would count the horizon twice.
double pair_integral(double theta_l, double sigma_l, double sigma_p, double horizon,
                     const LinearSdf& sdf, const IwasakiVisibility* vis) {
  const double open = gaussian_half_turn_integral(theta_l, sigma_l) * circular_gaussian_circle_integral(sigma_p);
  if (!sdf.on) return open * horizon;
  const double d = sdf.d + sdf.d_dtheta * (theta_l - sdf.theta);
  const double h = vis->kappa ? vis->kappa->h(sigma_l, sigma_p, d, sdf.d_dtheta, sdf.d_dphi)
                              : linear_visibility_ratio(sigma_l, sigma_p, d, sdf.d_dtheta, sdf.d_dphi);
  return open * std::min(h, horizon);
}

// The surface's height h = ω·n at direction (θ, φ) of a sample frame, and its partial derivatives:
// the straight boundary both horizon cuts below linearise or measure along.
struct SurfaceHeight {
  double h, h_dtheta, h_dphi;
};

SurfaceHeight surface_height(const ThreadFrame& tf, const dvec3& n, double theta, double phi) {
  const FiberDirection d = fiber_direction(tf, theta, phi);
  return {glm::dot(d.w, n), glm::dot(d.dw_dtheta, n), glm::dot(d.dw_dphi, n)};
}

// A longitudinal lobe's standard deviation γ for one tangent sample, widened by the tilts of the arc
// the sample stands for (RMS spread δ about its own tilt, TangentCurve::sample_tilt_spreads): a tilt
// change dα moves θ_i by cos φ_i·dα and θ_o by cos φ_o·dα, so θ_h by c·dα, c = (cos φ_i + cos φ_o)/2,
// and the sample's lobe averaged over its arc is N(θ_h; √(γ² + c²δ²)) (φ_i taken at φ_k). The
// midpoint samples alone put satin's 2.5° float highlight only where a sample's tilt is specular:
// with 15 samples a sun at 20° on the swatch is −13 to +43 % from the converged curve (64
// samples), with the lobes averaged over the arcs −3 to +7 % (docs/research/iwasaki.md, "Satin under skies").
double sample_lobe_width(double gamma, double tilt_spread, double phi_i, double phi_o) {
  const double c = 0.5 * (std::cos(phi_i) + std::cos(phi_o));
  return std::sqrt(gamma * gamma + c * c * tilt_spread * tilt_spread);
}

// Eq. 9 takes W out of the integral as its average over the SG (T at ξ_k), but a narrow
// longitudinal lobe (satin's float: γ_s 2.5°) keeps of the SG only a band along the thread's
// specular cone, where W differs from its mean over the SG: on a satin swatch a λ = 19 lobe is
// −18 to +44 % off with T at ξ_k, nearly all of it this factorisation (the exact shading factor
// with T at ξ_k: −15 to +43 %). T at the surface lobe's peak (θ_l, φ_k), at the SG's own λ, takes
// W where the product is: within ±6 % (docs/research/iwasaki.md, "Satin under skies"). One lookup serves both
// lobes: the volume lobe's peak lies next to it (separate lookups: within 0.7 % of the shared one).
// How much of T the lobes take at their peak: all of it from λ = 8, none at λ ≤ 2, linear in log λ
// between. For a sky's broad lobes (λ ≈ 2) Eq. 9's darkening and Eq. 13's frozen form's
// brightening cancel on linen (−10 % and +10 % at λ = 2; T at the peak for them puts linen's broad
// lobes +5 % on average), so they keep T at the axis until their shading factor is exact.
double lobe_peak_weight(double lambda) { return std::clamp(0.5 * std::log2(lambda / 2.0), 0.0, 1.0); }

}  // namespace

// The surface's own horizon as a visibility boundary in a sample frame. Eq. 9's T averages W over
// the lobe's part above the surface (W = 0 below it), so the shading factor must also integrate
// only there; the [−π/2, π/2]² square of Eq. 13 is the *sample's* hemisphere, which a tilted
// sample or a lobe near the horizon pokes below the surface. The height h(θ, φ) = ω(θ, φ)·n is
// known exactly, so its linearisation at the lobe's peak gives H in closed form
// (linear_visibility_ratio), like Eq. 12's V' for an occluder. Measured on the flat swatch
// (linen, 36 views, tables at grid 24): relative RMSE 10.8 % → 3.8 % under studio, whose sharp
// lights sit a few degrees above the horizon, and 6.3 % → 3.8 % under courtyard.
double horizon_ratio(const ThreadFrame& tf, const dvec3& n, double theta, double phi, double sigma_l,
                     double sigma_p) {
  const SurfaceHeight s = surface_height(tf, n, theta, phi);
  return linear_visibility_ratio(sigma_l, sigma_p, s.h, s.h_dtheta, s.h_dphi);
}

double lobe_horizon_fraction(const ThreadFrame& tf, const dvec3& n, double theta, double phi, double sigma_l,
                             double sigma_p) {
  const auto [h, h_dtheta, h_dphi] = surface_height(tf, n, theta, phi);
  const double ct = std::cos(theta);
  // Angular widths along θ and along φ (σ'·cos θ on the sphere), weighted by the squares of h's
  // angular gradient (h_θ, h_φ/cos θ), whose norm is √(1 − h²); at the poles of n, the mean.
  const double width_phi = sigma_p * ct;
  const double g_theta = h_dtheta * h_dtheta, g_phi = ct > 1e-6 ? h_dphi * h_dphi / (ct * ct) : 0.0;
  const double grad = g_theta + g_phi;
  const double mean = 0.5 * (sigma_l * sigma_l + width_phi * width_phi);
  const double width2 = grad > 1e-6 ? (g_theta * sigma_l * sigma_l + g_phi * width_phi * width_phi) / grad : mean;
  return sg_hemisphere_fraction(2.0 / width2, h);
}

double facet_horizon_factor(const SphericalGaussian& g, const dvec3& shading_normal, const dvec3& facet_normal) {
  if (facet_normal == dvec3(0.0) || glm::dot(shading_normal, facet_normal) > 1.0 - 1e-4) return 1.0;
  const dvec3 axis = glm::normalize(g.axis);
  const double shading = sg_hemisphere_fraction(g.sharpness, glm::dot(axis, shading_normal));
  const double facet = sg_hemisphere_fraction(g.sharpness, glm::dot(axis, facet_normal));
  return shading > 0.0 ? std::min(1.0, facet / shading) : 1.0;
}

namespace {
// SGs first … end − 1 of `sgs` (the visibility called with each one's index in `sgs`).
IwasakiTerms radiance_of(const ClothBsdf& bsdf, const WeightingTables& tables, const SurfaceFrame& frame,
                         const dvec3& wo, std::span<const SphericalGaussian> sgs, size_t first, size_t end,
                         const IwasakiVisibility* visibility) {
  if (tables.tangent_samples[0] != bsdf.sample_count(0) || tables.tangent_samples[1] != bsdf.sample_count(1))
    throw std::invalid_argument("iwasaki: tables were baked for other tangent sample counts");
  IwasakiTerms out;
  if (glm::dot(wo, frame.n) <= 0.0) return out;
  auto local = [&](const dvec3& w) { return dvec3(glm::dot(w, frame.u), glm::dot(w, frame.v), glm::dot(w, frame.n)); };
  const dvec3 wo_local = local(wo);

  for (size_t sg_index = first; sg_index < std::min(end, sgs.size()); ++sg_index) {
    // An SG whose axis is below the surface: its part above it, with λ' no broader than T's levels.
    const SphericalGaussian g = above_horizon(sgs[sg_index], frame.n, tables.lambdas.front());
    const dvec3 xi_local = local(g.axis);
    int s = 0;
    for (int j = 0; j < 2; ++j) {
      const ThreadParams& p = bsdf.fabric().threads[j];
      const int n = bsdf.sample_count(j);
      dvec3 surf(0.0), vol(0.0);
      for (int k = 0; k < n; ++k, ++s) {
        // Samples alike in tilt and spread give the same terms: the first, times their count.
        const double m = bsdf.sample_multiplicity(j, k);
        if (m == 0.0) continue;
        const ThreadFrame tf = thread_frame(frame, j, bsdf.tilt(j, k));
        const SgCircularSplit sg = split_sg(g, tf);  // Eq. 11
        const FiberAngles o = fiber_angles(tf, wo);
        const double gs = seed_bandwidth_from_std_dev(
                         sample_lobe_width(p.gamma_s, bsdf.tilt_spread(j, k), sg.phi_k, o.phi)),
                     gv = seed_bandwidth_from_std_dev(
                         sample_lobe_width(p.gamma_v, bsdf.tilt_spread(j, k), sg.phi_k, o.phi));
        const ScaledCircularGaussian light{1.0, sg.theta_k, sg.sigma_k};
        const ScaledCircularGaussian surface_lobe = product(light, longitudinal_lobe_as_circular(o.theta, gs));
        // Eq. 10: T at the SG's axis for the isotropic k_d part, and for both longitudinal lobes at
        // the surface lobe's peak (fiber_direction; blended with the axis's for broad SGs).
        const double T = std::max(tables.value(s, g.sharpness, xi_local, wo_local), 0.0);
        const double w_peak = lobe_peak_weight(g.sharpness);
        double T_lobe = T;
        if (w_peak > 0.0) {
          const dvec3 peak_local = local(fiber_direction(tf, surface_lobe.mu, sg.phi_k).w);
          const double T_peak = std::max(tables.value(s, g.sharpness, peak_local, wo_local), 0.0);
          T_lobe = std::lerp(T, T_peak, w_peak);
        }
        if (T <= 0.0 && T_lobe <= 0.0) continue;
        const double spread_k = separable_spread(g.sharpness, sg.theta_k, sg.sigma_k);
        LinearSdf sdf;
        if (visibility && visibility->sdf) {
          sdf.on = true;
          sdf.theta = sg.theta_k;
          visibility->sdf(int(sg_index), tf, sg.theta_k, sg.phi_k, sdf.d, sdf.d_dtheta, sdf.d_dphi);
        }

        // The smooth factors at a lobe's peak θ_i = θ_l, φ_i = φ_k. dω = cos θ dθ dφ gives the
        // second cos θ_l beside the model's own.
        auto smooth = [&](double theta_l, double& fresnel_r, double& geometry) {
          const double theta_d = 0.5 * (theta_l - o.theta);
          const double phi_d = wrap_angle(sg.phi_k - o.phi);
          const double cos_d = std::cos(theta_d);
          fresnel_r = fresnel_dielectric(p.eta, cos_d * std::cos(0.5 * phi_d));
          geometry = std::cos(theta_l) * std::cos(theta_l) / std::max(cos_d * cos_d, kModelDenominatorFloor);
          return std::cos(0.5 * phi_d);
        };
        // Surface lobe: g^u(θ_h; γ_s) ≈ g^c(θ_i; −θ_o, 2γ_s)/(√π γ_s), merged with the SG's.
        {
          const ScaledCircularGaussian& l = surface_lobe;
          const double sp = lobe_sigma_prime(sg.sigma_k, l.mu, sg.theta_k);
          double fr = 0, geo = 0;
          const double cos_half = smooth(l.mu, fr, geo);
          const double I = pair_integral(l.mu, l.sigma, sp,
                                         lobe_horizon_fraction(tf, frame.n, l.mu, sg.phi_k, l.sigma, sp), sdf, visibility);
          surf += dvec3(m * T_lobe * l.alpha * fr * cos_half * geo * I * lobe_spread(spread_k, l.sigma, sg.sigma_k));
        }
        // Volume lobe: (1 − k_d) g^u(θ_h; γ_v) part and the isotropic k_d part.
        {
          const ScaledCircularGaussian l = product(light, longitudinal_lobe_as_circular(o.theta, gv));
          double fr = 0, geo = 0;
          smooth(l.mu, fr, geo);
          const double t = 1.0 - fr;
          const double sp = lobe_sigma_prime(sg.sigma_k, l.mu, sg.theta_k);
          const double I = pair_integral(l.mu, l.sigma, sp,
                                         lobe_horizon_fraction(tf, frame.n, l.mu, sg.phi_k, l.sigma, sp), sdf, visibility);
          const double lobe = (1.0 - p.kd) * l.alpha * t * t * geo /
                              std::max(std::cos(l.mu) + std::cos(o.theta), kModelDenominatorFloor) * I *
                              lobe_spread(spread_k, l.sigma, sg.sigma_k);

          smooth(sg.theta_k, fr, geo);
          const double td = 1.0 - fr;
          const double spk = lobe_sigma_prime(sg.sigma_k, sg.theta_k, sg.theta_k);
          const double Ik =
              pair_integral(sg.theta_k, sg.sigma_k, spk,
                            lobe_horizon_fraction(tf, frame.n, sg.theta_k, sg.phi_k, sg.sigma_k, spk), sdf, visibility);
          const double iso = p.kd * td * td * geo /
                             std::max(std::cos(sg.theta_k) + std::cos(o.theta), kModelDenominatorFloor) * Ik * spread_k;
          vol += m * (T_lobe * lobe + T * iso) * p.albedo;
        }
      }
      dvec3 amplitude = visibility && visibility->open_share ? g.amplitude * visibility->open_share(int(sg_index))
                                                             : g.amplitude;
      if (visibility) amplitude *= facet_horizon_factor(sgs[sg_index], frame.n, visibility->facet_normal);
      out.surface += amplitude * surf / double(n);
      out.volume += amplitude * vol / double(n);
      out.thread_volume[j] += amplitude * vol / double(n);
    }
  }
  out.radiance = out.surface + out.volume;
  return out;
}

}  // namespace

IwasakiTerms iwasaki_radiance(const ClothBsdf& bsdf, const WeightingTables& tables, const SurfaceFrame& frame,
                              const dvec3& wo, std::span<const SphericalGaussian> sgs,
                              const IwasakiVisibility* visibility) {
  return radiance_of(bsdf, tables, frame, wo, sgs, 0, sgs.size(), visibility);
}

IwasakiTerms iwasaki_sg_radiance(const ClothBsdf& bsdf, const WeightingTables& tables, const SurfaceFrame& frame,
                                 const dvec3& wo, std::span<const SphericalGaussian> sgs, size_t k,
                                 const IwasakiVisibility* visibility) {
  return radiance_of(bsdf, tables, frame, wo, sgs, k, k + 1, visibility);
}

dvec3 facet_interpolated_radiance(std::span<const SphericalGaussian> sgs, std::span<const int> broad_slots,
                                  const std::array<std::span<const dvec3>, 3>& vertex_sgs, const dvec3& bary,
                                  const dvec3& shading_normal, const dvec3& facet_normal) {
  dvec3 sum(0.0);
  for (size_t k = 0; k < sgs.size(); ++k) {
    const dvec3 blended = bary[0] * vertex_sgs[0][k] + bary[1] * vertex_sgs[1][k] + bary[2] * vertex_sgs[2][k];
    const bool broad = k < broad_slots.size() && broad_slots[k] >= 0;
    sum += broad ? blended : blended * facet_horizon_factor(sgs[k], shading_normal, facet_normal);
  }
  return sum;
}

dvec3 facet_interpolated_radiance(std::span<const SphericalGaussian> sgs, std::span<const int> broad_slots,
                                  const std::array<std::span<const IwasakiTerms>, 3>& vertex_sgs, const dvec3& bary,
                                  const dvec3& shading_normal, const dvec3& facet_normal, const std::array<dvec3, 2>& tint,
                                  std::span<const dvec3> normal_map_ratios) {
  dvec3 sum(0.0);
  for (size_t k = 0; k < sgs.size(); ++k) {
    const dvec3 r = k < normal_map_ratios.size() ? normal_map_ratios[k] : dvec3(1.0);
    const std::array<dvec3, 2> volume_factor{tint[0] * r.y, tint[1] * r.z};
    dvec3 blended(0.0);
    for (int i = 0; i < 3; ++i) {
      IwasakiTerms t = vertex_sgs[i][k];
      t.surface *= r.x;
      blended += bary[i] * t.tinted(volume_factor);
    }
    const bool broad = k < broad_slots.size() && broad_slots[k] >= 0;
    sum += broad ? blended : blended * facet_horizon_factor(sgs[k], shading_normal, facet_normal);
  }
  return sum;
}

}  // namespace weft
