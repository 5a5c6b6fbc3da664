#include "core/microcylinder.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/fresnel.h"

namespace weft {

SurfaceFrame SurfaceFrame::from_normal_warp(dvec3 n, dvec3 warp) {
  SurfaceFrame f;
  f.n = glm::normalize(n);
  f.u = glm::normalize(warp - glm::dot(warp, f.n) * f.n);
  f.v = glm::cross(f.n, f.u);
  return f;
}

ThreadFrame thread_frame(const SurfaceFrame& s, int thread, double alpha) {
  const dvec3& along = thread == 0 ? s.u : s.v;
  const dvec3& axis = thread == 0 ? s.v : s.u;
  const double c = std::cos(alpha), sn = std::sin(alpha);
  return {c * along + sn * s.n, -sn * along + c * s.n, axis};
}

FiberAngles fiber_angles(const ThreadFrame& f, const dvec3& w) {
  const double wt = glm::clamp(glm::dot(w, f.t), -1.0, 1.0);
  const double wn = glm::dot(w, f.n_prime);
  const double wb = glm::dot(w, f.b);
  return {std::asin(wt), std::atan2(wb, wn), std::atan2(wt, wn)};
}

FiberDirection fiber_direction(const ThreadFrame& f, double theta, double phi) {
  const double ct = std::cos(theta), st = std::sin(theta), cp = std::cos(phi), sp = std::sin(phi);
  const dvec3 radial = cp * f.n_prime + sp * f.b;
  return {st * f.t + ct * radial, ct * f.t - st * radial, ct * (-sp * f.n_prime + cp * f.b)};
}

double normal_gaussian(double x, double gamma) {
  return std::exp(-x * x / (2.0 * gamma * gamma)) / (gamma * std::sqrt(2.0 * std::numbers::pi));
}

double masking_gaussian(double x) {
  constexpr double s = 20.0 * std::numbers::pi / 180.0;
  return std::exp(-x * x / (2.0 * s * s));
}

double masking_mix(double x, double y, double z) { return (1.0 - x) * y * z + x * std::min(y, z); }

double wrap_angle(double a) {
  constexpr double pi = std::numbers::pi;
  a = std::remainder(a, 2.0 * pi);  // [−π, π]
  return a <= -pi ? a + 2.0 * pi : a;
}

namespace {
struct HalfAngles {
  double theta_d, theta_h, phi_d;
};
HalfAngles half_angles(const FiberAngles& in, const FiberAngles& out) {
  return {(in.theta - out.theta) / 2.0, (in.theta + out.theta) / 2.0, wrap_angle(in.phi - out.phi)};
}
double effective_cos(const HalfAngles& h) { return std::cos(h.theta_d) * std::cos(h.phi_d / 2.0); }
}  // namespace

double surface_scattering(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out) {
  const HalfAngles h = half_angles(in, out);
  return fresnel_dielectric(p.eta, effective_cos(h)) * std::cos(h.phi_d / 2.0) *
         normal_gaussian(h.theta_h, p.gamma_s);
}

double volume_scattering_per_albedo(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out) {
  const HalfAngles h = half_angles(in, out);
  const double t = 1.0 - fresnel_dielectric(p.eta, effective_cos(h));
  const double lobe = (1.0 - p.kd) * normal_gaussian(h.theta_h, p.gamma_v) + p.kd;
  const double denom = std::max(std::cos(in.theta) + std::cos(out.theta), kModelDenominatorFloor);
  return t * t * lobe / denom;
}

dvec3 volume_scattering(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out) {
  return volume_scattering_per_albedo(p, in, out) * p.albedo;
}

glm::dvec2 scattering_split(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out) {
  const double cos_d = std::cos((in.theta - out.theta) / 2.0);
  const double inv = 1.0 / std::max(cos_d * cos_d, kModelDenominatorFloor);
  return glm::dvec2(surface_scattering(p, in, out), volume_scattering_per_albedo(p, in, out)) * inv;
}

dvec3 scattering(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out) {
  const double cos_d = std::cos((in.theta - out.theta) / 2.0);
  const double inv = 1.0 / std::max(cos_d * cos_d, kModelDenominatorFloor);
  return (dvec3(surface_scattering(p, in, out)) + volume_scattering(p, in, out)) * inv;
}

double masking(const FiberAngles& in, const FiberAngles& out) {
  return masking_mix(masking_gaussian(wrap_angle(in.phi - out.phi)), std::max(std::cos(in.phi), 0.0),
                     std::max(std::cos(out.phi), 0.0));
}

double projection(const FiberAngles& in, const FiberAngles& out) {
  return masking_mix(masking_gaussian(wrap_angle(in.psi - out.psi)), std::max(std::cos(in.psi), 0.0),
                     std::max(std::cos(out.psi), 0.0));
}

}  // namespace weft
