// The canonical model (docs/design.md §2) against closed forms and invariants it must keep.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/cloth_bsdf.h"
#include "core/fabric.h"
#include "core/fresnel.h"
#include "core/microcylinder.h"

using namespace weft;
constexpr double kPi = std::numbers::pi;

static Fabric preset(const std::string& name) { return load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics"); }

TEST(Fresnel, NormalIncidenceMatchesClosedForm) {
  for (double eta : {1.33, 1.46, 1.539}) {
    const double r0 = std::pow((eta - 1) / (eta + 1), 2);
    EXPECT_NEAR(fresnel_dielectric(eta, 1.0), r0, 1e-14);
  }
}

TEST(Fresnel, BrewsterAngleLeavesOnlySPolarisation) {
  const double eta = 1.5, tb = std::atan(eta);
  const double ci = std::cos(tb), ct = std::cos(std::asin(std::sin(tb) / eta));
  const double rs = (ci - eta * ct) / (ci + eta * ct);
  EXPECT_NEAR(fresnel_dielectric(eta, ci), 0.5 * rs * rs, 1e-14);
}

TEST(Fresnel, GrazingIsTotalAndMonotone) {
  EXPECT_NEAR(fresnel_dielectric(1.46, 0.0), 1.0, 1e-12);
  double prev = 2.0;
  for (int i = 0; i <= 100; ++i) {
    const double f = fresnel_dielectric(1.46, i / 100.0);
    EXPECT_LT(f, prev + 1e-15);
    prev = f;
  }
}

TEST(Gaussians, NormalGaussianIsSeedGuWithSqrt2Gamma) {
  // seed 000 Eq. 3–4: g^u(x;0,σ) = exp(−x²/σ²)/(√π σ); docs/design.md: σ = √2·γ.
  for (double gamma : {0.05, 0.2, 1.0})
    for (double x : {-0.3, 0.0, 0.1, 0.7}) {
      const double s = std::sqrt(2.0) * gamma;
      EXPECT_NEAR(normal_gaussian(x, gamma), std::exp(-x * x / (s * s)) / (std::sqrt(kPi) * s), 1e-12);
    }
}

TEST(Gaussians, NormalGaussianHasUnitMass) {
  const double gamma = 0.1;
  double sum = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double x = -1.0 + 2.0 * (i + 0.5) / n;
    sum += normal_gaussian(x, gamma) * 2.0 / n;
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
}

TEST(Gaussians, MaskingGaussianIsOneSigmaAtTwentyDegrees) {
  EXPECT_DOUBLE_EQ(masking_gaussian(0.0), 1.0);
  EXPECT_NEAR(masking_gaussian(20.0 * kPi / 180.0), std::exp(-0.5), 1e-14);
}

TEST(Masking, MixInterpolatesProductAndMinimum) {
  EXPECT_DOUBLE_EQ(masking_mix(0.0, 0.3, 0.5), 0.15);
  EXPECT_DOUBLE_EQ(masking_mix(1.0, 0.3, 0.5), 0.3);
  EXPECT_DOUBLE_EQ(masking_mix(0.25, 0.4, 0.8), 0.75 * 0.32 + 0.25 * 0.4);
}

TEST(Angles, WrapToHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(wrap_angle(kPi), kPi);
  EXPECT_DOUBLE_EQ(wrap_angle(-kPi), kPi);
  EXPECT_NEAR(wrap_angle(3 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_NEAR(wrap_angle(-3 * kPi / 2), kPi / 2, 1e-15);
  EXPECT_NEAR(wrap_angle(0.3), 0.3, 1e-15);
}

TEST(Frames, ThreadFramesAreOrthonormalAndFollowDesign) {
  const SurfaceFrame s = SurfaceFrame::from_normal_warp({0.1, 0.2, 1.0}, {1, 0.3, 0});
  for (int thread = 0; thread < 2; ++thread)
    for (double a : {-kPi / 2, -0.4, 0.0, 0.7}) {
      const ThreadFrame f = thread_frame(s, thread, a);
      EXPECT_NEAR(glm::length(f.t), 1, 1e-12);
      EXPECT_NEAR(glm::length(f.n_prime), 1, 1e-12);
      EXPECT_NEAR(glm::dot(f.t, f.n_prime), 0, 1e-12);
      EXPECT_NEAR(glm::dot(f.t, f.b), 0, 1e-12);
      EXPECT_NEAR(glm::dot(f.n_prime, f.b), 0, 1e-12);
      const dvec3 along = thread == 0 ? s.u : s.v;
      EXPECT_NEAR(glm::dot(f.t, along), std::cos(a), 1e-12);
      EXPECT_NEAR(glm::dot(f.t, s.n), std::sin(a), 1e-12);
      EXPECT_NEAR(glm::dot(f.b, thread == 0 ? s.v : s.u), 1, 1e-12);
    }
}

TEST(Frames, FiberAnglesOfKnownDirections) {
  const ThreadFrame f = thread_frame(SurfaceFrame{}, 0, 0.0);  // t=+x, n'=+z, b=+y
  FiberAngles a = fiber_angles(f, {0, 0, 1});
  EXPECT_NEAR(a.theta, 0, 1e-15);
  EXPECT_NEAR(a.phi, 0, 1e-15);
  EXPECT_NEAR(a.psi, 0, 1e-15);
  a = fiber_angles(f, glm::normalize(dvec3(1, 0, 1)));
  EXPECT_NEAR(a.theta, kPi / 4, 1e-14);
  EXPECT_NEAR(a.psi, kPi / 4, 1e-14);
  a = fiber_angles(f, glm::normalize(dvec3(0, 1, 1)));
  EXPECT_NEAR(a.theta, 0, 1e-14);
  EXPECT_NEAR(a.phi, kPi / 4, 1e-14);
}

// fiber_direction inverts fiber_angles on a tilted frame, and its derivatives are those of the
// direction by central differences.
TEST(Frames, FiberDirectionInvertsFiberAngles) {
  const SurfaceFrame s = SurfaceFrame::from_normal_warp(glm::normalize(dvec3(0.2, -0.3, 1.0)), dvec3(1, 0.4, 0));
  const ThreadFrame f = thread_frame(s, 1, glm::radians(-25.0));
  for (double theta : {-1.2, -0.3, 0.0, 0.7, 1.4})
    for (double phi : {-2.9, -1.0, 0.2, 1.6, 3.0}) {
      const FiberDirection d = fiber_direction(f, theta, phi);
      EXPECT_NEAR(glm::length(d.w), 1.0, 1e-14);
      const FiberAngles a = fiber_angles(f, d.w);
      EXPECT_NEAR(a.theta, theta, 1e-12);
      EXPECT_NEAR(a.phi, phi, 1e-12);
      const double e = 1e-6;
      const dvec3 dt = (fiber_direction(f, theta + e, phi).w - fiber_direction(f, theta - e, phi).w) / (2 * e);
      const dvec3 dp = (fiber_direction(f, theta, phi + e).w - fiber_direction(f, theta, phi - e).w) / (2 * e);
      EXPECT_NEAR(glm::length(dt - d.dw_dtheta), 0.0, 1e-8);
      EXPECT_NEAR(glm::length(dp - d.dw_dphi), 0.0, 1e-8);
    }
}

// The RMS tilt over each sample's arc: Δα/√12 on a ramp (the uniform distribution's), 0 on a
// straight stretch.
TEST(TangentCurve, TiltSpreadsOverEachSamplesArc) {
  const TangentCurve ramp({-25, 25}, {1});
  for (double d : ramp.sample_tilt_spreads(2)) EXPECT_NEAR(d, glm::radians(25.0) / std::sqrt(12.0), 1e-5);
  EXPECT_NEAR(TangentCurve({7}, {}).sample_tilt_spreads(3)[1], 0.0, 1e-15);
  // Satin's first thread at 15 samples: the middle sample lies within the flat 0° stretch.
  const Fabric satin = preset("polyester_satin_charmeuse");
  const auto d = satin.threads[0].curve.sample_tilt_spreads(15);
  EXPECT_NEAR(d[7], 0.0, 1e-15);
  EXPECT_GT(d[4], glm::radians(1.0));
}

TEST(TangentCurve, SamplesAtArcLengthMidpoints) {
  const TangentCurve c({-25, 25}, {1});
  const auto t = c.sample_tilts(2);
  EXPECT_NEAR(t[0], glm::radians(-12.5), 1e-14);
  EXPECT_NEAR(t[1], glm::radians(12.5), 1e-14);
  // Satin's first thread: Λ = 10, the first sample at s = 0.5 lies in the flat −32° segment.
  const Fabric satin = preset("polyester_satin_charmeuse");
  const auto s = satin.threads[0].curve.sample_tilts(10);
  EXPECT_NEAR(satin.threads[0].curve.total_length(), 9.98, 1e-12);
  EXPECT_NEAR(s[0], glm::radians(-32.0), 1e-12);
  EXPECT_NEAR(s[9], glm::radians(32.0), 1e-12);
  // Every sample lies on the curve between its vertices' tilts.
  for (double a : s) EXPECT_LE(std::abs(a), glm::radians(32.0) + 1e-12);
}

TEST(TangentCurve, ZeroLengthSegmentIsAJump) {
  // Velvet's second thread jumps from −55° to +55°: no sample may fall strictly between.
  const Fabric velvet = preset("velvet");
  for (int n : {2, 7, 32, 101})
    for (double a : velvet.threads[1].curve.sample_tilts(n))
      EXPECT_TRUE(a <= glm::radians(-55.0) + 1e-12 || a >= glm::radians(55.0) - 1e-12) << n << " " << a;
}

TEST(TangentCurve, EveryPresetSamplesUniformlyInArcLength) {
  // The mean tilt over many samples equals the curve's arc-length average, computed here
  // segment by segment (mean of a linear segment = mean of its ends).
  for (const auto& name : list_fabric_presets(WEFT_SOURCE_ASSETS "/fabrics")) {
    const Fabric f = preset(name);
    for (const auto& th : f.threads) {
      const auto& o = th.curve.offsets_deg();
      const auto& l = th.curve.lengths();
      double expect = o.size() == 1 ? o[0] : 0.0;
      for (size_t i = 0; i < l.size(); ++i) expect += 0.5 * (o[i] + o[i + 1]) * l[i] / th.curve.total_length();
      double mean = 0;
      const auto t = th.curve.sample_tilts(20000);
      for (double a : t) mean += glm::degrees(a) / t.size();
      EXPECT_NEAR(mean, expect, 1e-3) << name;
    }
  }
}

// A satin's float is a flat run of its warp's curve: several of its arc-midpoint samples lie at
// tilt 0 with no spread, and each run of alike samples is counted once, by its first.
TEST(ClothBsdf, AlikeSamplesAreCountedByTheFirst) {
  const ClothBsdf bsdf(preset("polyester_satin_charmeuse"), {15, 3});
  for (int j = 0; j < 2; ++j) {
    int total = 0, merged = 0;
    for (int k = 0; k < bsdf.sample_count(j); ++k) {
      const int m = bsdf.sample_multiplicity(j, k);
      total += m;
      int alike = 0;
      bool earlier = false;
      for (int q = 0; q < bsdf.sample_count(j); ++q) {
        const bool same = bsdf.tilt(j, q) == bsdf.tilt(j, k) && bsdf.tilt_spread(j, q) == bsdf.tilt_spread(j, k);
        alike += same ? 1 : 0;
        earlier = earlier || (same && q < k);
      }
      EXPECT_EQ(m, earlier ? 0 : alike) << "thread " << j << " sample " << k;
      merged += m == 0 ? 1 : 0;
    }
    EXPECT_EQ(total, bsdf.sample_count(j));
    if (j == 0) {
      EXPECT_GE(merged, 3) << "the float's flat run and its two ends";
    }
  }
  const ClothBsdf linen(preset("linen_plain"), 15);  // a plain weave's curves bend everywhere
  for (int k = 0; k < 15; ++k) EXPECT_EQ(linen.sample_multiplicity(0, k), 1);
}

TEST(TangentCurve, RejectsMismatchedLengths) {
  EXPECT_THROW(TangentCurve({0, 1, 2}, {1}), std::invalid_argument);
  EXPECT_THROW(TangentCurve({0, 1}, {0}), std::invalid_argument);
  EXPECT_THROW(TangentCurve({0, 1}, {-1}), std::invalid_argument);
}

TEST(Scattering, SurfaceLobeMatchesHandComputation) {
  ThreadParams p;
  p.eta = 1.46;
  p.gamma_s = glm::radians(12.0);
  const FiberAngles in{0.3, 0.4, 0.0}, out{-0.1, -0.2, 0.0};
  const double td = 0.2, th = 0.1, pd = 0.6;
  const double c = std::cos(td) * std::cos(pd / 2);
  EXPECT_NEAR(surface_scattering(p, in, out),
              fresnel_dielectric(1.46, c) * std::cos(pd / 2) * normal_gaussian(th, p.gamma_s), 1e-14);
  const dvec3 fv = volume_scattering(p, in, out);
  const double t = 1 - fresnel_dielectric(1.46, c);
  const double lobe = (1 - p.kd) * normal_gaussian(th, p.gamma_v) + p.kd;
  EXPECT_NEAR(fv.r, t * t * lobe / (std::cos(0.3) + std::cos(-0.1)) * p.albedo.r, 1e-14);
  const dvec3 fs = scattering(p, in, out);
  EXPECT_NEAR(fs.g, (surface_scattering(p, in, out) + fv.g) / (std::cos(td) * std::cos(td)), 1e-13);
}

TEST(ClothModel, WeightsAreAPartitionBoundedByOne) {
  // M ≤ 1 and Q ≥ Σ_j a_j⟨P⟩_j, so Σ_j ⟨W⟩_j ≤ 1; without the (1 − a₁ − a₂) term and with
  // M = 1 it is exactly 1. Checked for random directions on every preset.
  std::mt19937 rng(7);
  std::normal_distribution<double> nd;
  for (const auto& name : list_fabric_presets(WEFT_SOURCE_ASSETS "/fabrics")) {
    const ClothBsdf bsdf(preset(name), 16);
    auto point = bsdf.at(SurfaceFrame{});
    std::vector<double> w(bsdf.total_samples());
    for (int i = 0; i < 2000; ++i) {
      dvec3 wi = glm::normalize(dvec3(nd(rng), nd(rng), std::abs(nd(rng))));
      dvec3 wo = glm::normalize(dvec3(nd(rng), nd(rng), std::abs(nd(rng))));
      const double q = point.weights(wi, wo, w);
      double sum = 0;
      for (int j = 0, s = 0; j < 2; ++j)
        for (int k = 0; k < bsdf.sample_count(j); ++k, ++s) sum += w[s] / bsdf.sample_count(j);
      ASSERT_GE(q, 0.0);
      ASSERT_LE(sum, 1.0 + 1e-12) << name;
    }
  }
}

TEST(ClothModel, FiniteAndNonNegativeOverAMillionDirectionPairs) {
  // Random pairs, a fifth of them grazing (within 1e-6 of the horizon), a tenth exactly
  // along a tangent sample of either thread, some both.
  std::mt19937 rng(2024);
  std::normal_distribution<double> nd;
  std::uniform_real_distribution<double> ud(0, 1);
  const auto names = list_fabric_presets(WEFT_SOURCE_ASSETS "/fabrics");
  std::vector<ClothBsdf> bsdfs;
  for (const auto& n : names) bsdfs.emplace_back(preset(n), 8);
  auto draw = [&](const ClothBsdf& b) {
    const double r = ud(rng);
    if (r < 0.2) {
      const double phi = 2 * kPi * ud(rng);
      return glm::normalize(dvec3(std::cos(phi), std::sin(phi), 1e-6 * ud(rng)));
    }
    if (r < 0.3) {
      const int j = ud(rng) < 0.5 ? 0 : 1;
      const int k = std::min(int(ud(rng) * b.sample_count(j)), b.sample_count(j) - 1);
      const dvec3 t = thread_frame(SurfaceFrame{}, j, b.tilt(j, k)).t;
      return ud(rng) < 0.5 ? t : -t;
    }
    return glm::normalize(dvec3(nd(rng), nd(rng), nd(rng)));
  };
  long long checked = 0;
  for (int i = 0; i < 1000000; ++i) {
    const ClothBsdf& b = bsdfs[i % bsdfs.size()];
    thread_local std::vector<ClothBsdf::Point> points;
    if (points.size() < bsdfs.size())
      for (const auto& bb : bsdfs) points.push_back(bb.at(SurfaceFrame{}));
    const dvec3 wi = draw(b), wo = draw(b);
    const dvec3 f = points[i % bsdfs.size()].integrand(wi, wo);
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(std::isfinite(f[c])) << names[i % names.size()] << " wi " << wi.x << "," << wi.y << "," << wi.z;
      ASSERT_GE(f[c], 0.0);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 1000000);
}
