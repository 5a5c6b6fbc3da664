#include "methods/mdfrot/mdfrot.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/fresnel.h"
#include "methods/sg_lights.h"

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;

double pow5(double x) { return x * x * x * x * x; }

// Ashikhmin–Shirley for one thread at one sample, the distribution at the rotated h̃.
dvec3 thread_sample(const MdfrotThread& t, const dvec3& h_tilde, double n_dot_l, double n_dot_v, double k_dot_h) {
  dvec3 f = t.diffuse * (28.0 / (23.0 * kPi) * (1.0 - t.f0) * (1.0 - pow5(1.0 - 0.5 * n_dot_l)) *
                         (1.0 - pow5(1.0 - 0.5 * n_dot_v)));
  if (h_tilde.z <= 0.0) return f;
  const double xy = h_tilde.x * h_tilde.x + h_tilde.y * h_tilde.y;
  // h̃ is not unit (R̃ is approximate): the exponent takes its direction within the plane.
  const double e = xy > 1e-12 ? (t.n_along * h_tilde.x * h_tilde.x + t.n_across * h_tilde.y * h_tilde.y) / xy
                              : t.n_along;
  const double fresnel = t.f0 + (1.0 - t.f0) * pow5(1.0 - k_dot_h);
  const double spec = std::sqrt((t.n_along + 1.0) * (t.n_across + 1.0)) / (8.0 * kPi) * std::pow(h_tilde.z, e) /
                      (std::max(k_dot_h, 1e-4) * std::max(n_dot_l, n_dot_v)) * fresnel;
  return f + dvec3(spec);
}
}  // namespace

MdfrotParams mdfrot_params(const Fabric& fabric, int samples) {
  if (samples < 1 || samples > kMdfrotMaxSamples)
    throw std::invalid_argument("mdfrot: samples per thread must be within 1.." + std::to_string(kMdfrotMaxSamples));
  const ClothBsdf bsdf(fabric, samples);
  const double total = fabric.threads[0].coverage + fabric.threads[1].coverage;
  MdfrotParams p;
  for (int j = 0; j < 2; ++j) {
    const ThreadParams& t = fabric.threads[j];
    MdfrotThread& m = p.threads[j];
    m.diffuse = t.albedo;
    m.f0 = fresnel_dielectric(t.eta, 1.0);
    m.n_along = 1.0 / (t.gamma_s * t.gamma_s);
    m.n_across = 1.0;
    m.weight = total > 0.0 ? t.coverage / total : 0.5;
    m.tilts.resize(samples);
    for (int k = 0; k < samples; ++k) m.tilts[k] = bsdf.tilt(j, k);
  }
  return p;
}

dvec3 mdfrot_perturbed_normal(double alpha, double beta) {
  return glm::normalize(dvec3(-std::sin(alpha), std::sin(beta), std::cos(alpha) * std::cos(beta)));
}

dvec3 mdfrot_rotate_half(const dvec3& nt, const dvec3& h) {
  return dvec3(nt.z * h.x - nt.x * h.z, -nt.x * nt.y * h.x + (1.0 - nt.y * nt.y) * h.y + nt.y * nt.z * h.z,
               glm::dot(nt, h));
}

dvec3 mdfrot_brdf(const MdfrotParams& p, const SurfaceFrame& frame, const dvec3& wi, const dvec3& wo) {
  const double nl = glm::dot(frame.n, wi), nv = glm::dot(frame.n, wo);
  if (nl <= 0.0 || nv <= 0.0) return dvec3(0.0);
  const dvec3 h = glm::normalize(wi + wo);
  const double kh = std::clamp(glm::dot(wi, h), 0.0, 1.0);
  dvec3 f(0.0);
  for (int j = 0; j < 2; ++j) {
    const MdfrotThread& t = p.threads[j];
    const dvec3 along = j == 0 ? frame.u : frame.v, across = j == 0 ? frame.v : frame.u;
    const dvec3 hl(glm::dot(h, along), glm::dot(h, across), glm::dot(h, frame.n));
    dvec3 sum(0.0);
    const int n = static_cast<int>(t.tilts.size());
    for (int k = 0; k < n; ++k) {
      const double beta = k % 2 == 0 ? p.bulge : -p.bulge;
      const dvec3 nt = mdfrot_perturbed_normal(t.tilts[k], beta);
      sum += thread_sample(t, mdfrot_rotate_half(nt, hl), nl, nv, kh);
    }
    f += t.weight * sum / double(n);
  }
  return f;
}

dvec3 mdfrot_radiance(const MdfrotParams& p, const SurfaceFrame& frame, const dvec3& wo,
                      std::span<const SphericalGaussian> sgs) {
  if (glm::dot(frame.n, wo) <= 0.0) return dvec3(0.0);
  dvec3 l(0.0);
  for (const auto& g : sgs) l += irradiance(g, frame.n) * mdfrot_brdf(p, frame, lift_above_horizon(g.axis, frame.n), wo);
  return l;
}

}  // namespace weft
