#pragma once
// The canonical microcylinder model, per tangent sample (Sadeghi et al. 2013 as restated in
// seed 000 Eq. 5–7, with the conventions of docs/design.md §2). This file is the model's only
// definition: the reference, the baker and every test call it.
#include <glm/glm.hpp>

#include "core/tangent_curve.h"

namespace weft {

using glm::dvec3;

// Shading frame at a surface point: normal n, warp u (thread 1), weft v = n × u (thread 2).
struct SurfaceFrame {
  dvec3 n{0, 0, 1};
  dvec3 u{1, 0, 0};
  dvec3 v{0, 1, 0};
  // Builds an orthonormal frame from a normal and an approximate warp direction.
  static SurfaceFrame from_normal_warp(dvec3 n, dvec3 warp);
};

// Local frame of one tangent sample: tangent t, tilted normal n', cylinder axis-normal b.
struct ThreadFrame {
  dvec3 t, n_prime, b;
};

// thread 0 is docs/design.md's thread 1 (along u), thread 1 is thread 2 (along v). α in radians.
ThreadFrame thread_frame(const SurfaceFrame& s, int thread, double alpha);

// θ = asin(ω·t), φ = atan2(ω·b, ω·n'), ψ = atan2(ω·t, ω·n').
struct FiberAngles {
  double theta, phi, psi;
};
FiberAngles fiber_angles(const ThreadFrame& f, const dvec3& w);
// fiber_angles' inverse: the direction at (θ, φ) of frame f, sin θ·t + cos θ·(cos φ·n' + sin φ·b),
// with its derivatives in θ and φ (what a linearisation about a lobe's peak needs).
struct FiberDirection {
  dvec3 w, dw_dtheta, dw_dphi;
};
FiberDirection fiber_direction(const ThreadFrame& f, double theta, double phi);

// Scattering parameters of one thread; angles in radians, A already scaled.
struct ThreadParams {
  double eta = 1.46;
  dvec3 albedo{0.5};     // A (RGB)
  double kd = 0.3;       // k_d
  double gamma_s = 0.2;  // γ_s, standard deviation of the surface lobe
  double gamma_v = 0.4;  // γ_v, of the volume lobe
  double coverage = 0.5; // a_j
  TangentCurve curve;
};

// N(x;γ) = exp(−x²/(2γ²)) / (γ√(2π)): Table II's γ are standard deviations.
double normal_gaussian(double x, double gamma);
// Unit-height masking Gaussian u(x) = exp(−x²/(2·(20°)²)).
double masking_gaussian(double x);
// D(x,y,z) = (1−x)·y·z + x·min(y,z).
double masking_mix(double x, double y, double z);
// Wraps an angle difference to (−π, π].
double wrap_angle(double a);

// f_s = (f_rs + f_rv) / cos²θ_d, RGB (f_rs is white).
dvec3 scattering(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out);
// The separate lobes, for tests and for methods that split them.
double surface_scattering(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out);  // f_rs
dvec3 volume_scattering(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out);    // f_rv
// f_rv per unit albedo (f_rv = A times it): the part a texture's texel scales.
double volume_scattering_per_albedo(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out);
// f_s split as (surface part, volume part per unit albedo): f_s = x + A·y.
glm::dvec2 scattering_split(const ThreadParams& p, const FiberAngles& in, const FiberAngles& out);
// M: shadowing–masking; P: projection.
double masking(const FiberAngles& in, const FiberAngles& out);
double projection(const FiberAngles& in, const FiberAngles& out);

// Denominators the model divides by (cos²θ_d, cos θ_i + cos θ_o) vanish only when both
// directions run along the thread; they are floored here so the model stays finite there.
inline constexpr double kModelDenominatorFloor = 1e-12;
// Q at or below this gives W = 0 (docs/design.md §2).
inline constexpr double kQFloor = 1e-8;

}  // namespace weft
