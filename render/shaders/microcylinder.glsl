// The microcylinder model of docs/design.md §2 in GLSL ES 3.0, for runtime methods that evaluate it
// directly (sgpoint, the weave layer). Mirrors render/core/microcylinder.cpp + cloth_bsdf.cpp term by term;
// tests/gpu/microcylinder_parity_test.cpp pins the two together.
// Needs: #define MAX_TANGENT_SAMPLES before inclusion.

const float PI = 3.14159265358979;
const float DENOMINATOR_FLOOR = 1e-12;  // kModelDenominatorFloor
const float Q_FLOOR = 1e-8;             // kQFloor

struct Thread {
  float eta;
  vec3 albedo;     // A
  float kd;
  float gamma_s;   // radians
  float gamma_v;
  float coverage;  // a_j
  int samples;     // N_j
};

uniform Thread u_threads[2];
// Thread 0's N_0 tilts, then thread 1's at MAX_TANGENT_SAMPLES; four to a vec4, because some
// drivers (NVIDIA's) give each element of a uniform array a whole register and a program 1024.
uniform vec4 u_tilts[MAX_TANGENT_SAMPLES / 2];
float thread_tilt(int s) { return u_tilts[s >> 2][s & 3]; }

struct FiberAngles { float theta; float phi; float psi; };

float normal_gaussian(float x, float gamma) {
  return exp(-x * x / (2.0 * gamma * gamma)) / (gamma * sqrt(2.0 * PI));
}
float masking_gaussian(float x) {
  const float s = 20.0 * PI / 180.0;
  return exp(-x * x / (2.0 * s * s));
}
float masking_mix(float x, float y, float z) { return (1.0 - x) * y * z + x * min(y, z); }
float wrap_angle(float a) {
  a = a - 2.0 * PI * floor((a + PI) / (2.0 * PI));  // [−π, π)
  return a <= -PI ? a + 2.0 * PI : a;
}
float fresnel_dielectric(float eta, float cos_i) {
  cos_i = clamp(cos_i, 0.0, 1.0);
  float sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0) return 1.0;
  float cos_t = sqrt(1.0 - sin2_t);
  float r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  float r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (r_s * r_s + r_p * r_p);
}

// Thread frame of docs/design.md §2: t = cos α·along + sin α·n, n' = −sin α·along + cos α·n, b = axis.
struct SampleFrame { vec3 t; vec3 np; };
SampleFrame sample_frame(vec3 along, vec3 n, float alpha) {
  float c = cos(alpha), s = sin(alpha);
  return SampleFrame(c * along + s * n, -s * along + c * n);
}
// fiber_angles_in: the angles in the sample's frame (t, n') already turned by α.
FiberAngles fiber_angles_in(vec3 t, vec3 np, vec3 axis, vec3 w) {
  float wt = clamp(dot(w, t), -1.0, 1.0);
  float wn = dot(w, np);
  // asin is only good to ~4e-4 on llvmpipe (GLSL ES allows 4096 ULP); atan of the same
  // angle is ~20x tighter, and (1−x)(1+x) keeps the cosine exact near the poles.
  return FiberAngles(atan(wt, sqrt((1.0 - wt) * (1.0 + wt))), atan(dot(w, axis), wn), atan(wt, wn));
}
FiberAngles fiber_angles(vec3 along, vec3 axis, vec3 n, float alpha, vec3 w) {
  SampleFrame f = sample_frame(along, n, alpha);
  return fiber_angles_in(f.t, f.np, axis, w);
}

// microcylinder.cpp's fiber_direction: fiber_angles' inverse in frame (t, n', b), with its
// derivatives in θ and φ.
struct FiberDirection {
  vec3 w, dw_dtheta, dw_dphi;
};
FiberDirection fiber_direction(vec3 t, vec3 np, vec3 b, float theta, float phi) {
  float ct = cos(theta), st = sin(theta), cp = cos(phi), sp = sin(phi);
  vec3 radial = cp * np + sp * b;
  return FiberDirection(st * t + ct * radial, ct * t - st * radial, ct * (-sp * np + cp * b));
}

// f_s as (surface part, volume part per unit albedo): f_s = x + A·y (microcylinder.cpp's
// surface_scattering and volume_scattering over cos² θ_d).
vec2 scattering_split(Thread p, FiberAngles i, FiberAngles o) {
  float theta_d = 0.5 * (i.theta - o.theta), theta_h = 0.5 * (i.theta + o.theta);
  float phi_d = wrap_angle(i.phi - o.phi);
  float c = cos(theta_d) * cos(0.5 * phi_d);
  float fr = fresnel_dielectric(p.eta, c);
  float f_rs = fr * cos(0.5 * phi_d) * normal_gaussian(theta_h, p.gamma_s);
  float t = 1.0 - fr;
  float lobe = (1.0 - p.kd) * normal_gaussian(theta_h, p.gamma_v) + p.kd;
  float f_rv = t * t * lobe / max(cos(i.theta) + cos(o.theta), DENOMINATOR_FLOOR);
  return vec2(f_rs, f_rv) / max(cos(theta_d) * cos(theta_d), DENOMINATOR_FLOOR);
}
vec3 scattering(Thread p, FiberAngles i, FiberAngles o) {
  vec2 f = scattering_split(p, i, o);
  return vec3(f.x) + f.y * p.albedo;
}
float masking_term(FiberAngles i, FiberAngles o) {
  return masking_mix(masking_gaussian(wrap_angle(i.phi - o.phi)), max(cos(i.phi), 0.0), max(cos(o.phi), 0.0));
}
float projection_term(FiberAngles i, FiberAngles o) {
  return masking_mix(masking_gaussian(wrap_angle(i.psi - o.psi)), max(cos(i.psi), 0.0), max(cos(o.psi), 0.0));
}

// Q(ω_i, ω_o) = Σ_j a_j ⟨P⟩_j + (1 − a_1 − a_2) · max(n·ω_o, 0): ClothBsdf::Point::q.
float cloth_q(vec3 n, vec3 u, vec3 wi, vec3 wo) {
  vec3 v = cross(n, u);
  float q = (1.0 - u_threads[0].coverage - u_threads[1].coverage) * max(dot(n, wo), 0.0);
  for (int j = 0; j < 2; ++j) {
    vec3 along = j == 0 ? u : v, axis = j == 0 ? v : u;
    float sum = 0.0;
    for (int k = 0; k < u_threads[j].samples; ++k) {
      float alpha = thread_tilt(j * MAX_TANGENT_SAMPLES + k);
      sum += projection_term(fiber_angles(along, axis, n, alpha, wi), fiber_angles(along, axis, n, alpha, wo));
    }
    q += u_threads[j].coverage * sum / float(u_threads[j].samples);
  }
  return q;
}

// Thread p with both lobes widened by the variance `widen2` (radians²): γ² → γ² + widen2.
Thread widened(Thread p, float widen2) {
  if (widen2 <= 0.0) return p;
  p.gamma_s = sqrt(p.gamma_s * p.gamma_s + widen2);
  p.gamma_v = sqrt(p.gamma_v * p.gamma_v + widen2);
  return p;
}

// What the integrand needs of ω_o alone, per tangent sample of each thread (thread j's sample k
// at j·MAX_TANGENT_SAMPLES + k): the sample's frame and ω_o's angles in it. A quadrature over many
// ω_i at one point (broad_lobe_quadrature.glsl) takes it once.
struct ClothView {
  vec3 n, u, wo;
  vec3 t[2 * MAX_TANGENT_SAMPLES], np[2 * MAX_TANGENT_SAMPLES];
  FiberAngles o[2 * MAX_TANGENT_SAMPLES];
};
ClothView cloth_view(vec3 n, vec3 u, vec3 wo) {
  ClothView cv;
  cv.n = n;
  cv.u = u;
  cv.wo = wo;
  vec3 v = cross(n, u);
  for (int j = 0; j < 2; ++j) {
    vec3 along = j == 0 ? u : v, axis = j == 0 ? v : u;
    for (int k = 0; k < u_threads[j].samples; ++k) {
      int s = j * MAX_TANGENT_SAMPLES + k;
      SampleFrame f = sample_frame(along, n, thread_tilt(s));
      cv.t[s] = f.t;
      cv.np[s] = f.np;
      cv.o[s] = fiber_angles_in(cv.t[s], cv.np[s], axis, wo);
    }
  }
  return cv;
}

// Σ_j ⟨f_s · W · cos θ_i⟩_j for the view's frame (n, u, v = n × u), each lobe widened by `widen2`,
// split as (surface part, thread 0's volume part per unit albedo, thread 1's): the integrand is
// x + A_0·y + A_1·z (ClothBsdf::Point::integrand_split). W = a_j·M·P/Q with Q common to both
// threads, so one sweep over the samples sums both ⟨P⟩ (for Q) and ⟨f_s·M·P·cos θ_i⟩, and Q
// divides at the end.
vec3 cloth_integrand_split_view(ClothView cv, vec3 wi, float widen2) {
  vec3 n = cv.n, u = cv.u;
  if (dot(n, wi) <= 0.0 || dot(n, cv.wo) <= 0.0) return vec3(0.0);
  vec3 v = cross(n, u);
  float q = (1.0 - u_threads[0].coverage - u_threads[1].coverage) * max(dot(n, cv.wo), 0.0);
  vec2 sums[2];
  for (int j = 0; j < 2; ++j) {
    vec3 axis = j == 0 ? v : u;
    Thread thread = widened(u_threads[j], widen2);
    float p_sum = 0.0;
    vec2 sum = vec2(0.0);
    for (int k = 0; k < u_threads[j].samples; ++k) {
      int s = j * MAX_TANGENT_SAMPLES + k;
      FiberAngles fi = fiber_angles_in(cv.t[s], cv.np[s], axis, wi);
      FiberAngles fo = cv.o[s];
      float p = projection_term(fi, fo);
      p_sum += p;
      if (p <= 0.0) continue;
      float mp = masking_term(fi, fo) * p;
      if (mp <= 0.0) continue;
      sum += scattering_split(thread, fi, fo) * (mp * cos(fi.theta));
    }
    float inv_n = 1.0 / float(u_threads[j].samples);
    q += u_threads[j].coverage * p_sum * inv_n;
    sums[j] = sum * (u_threads[j].coverage * inv_n);
  }
  if (q <= Q_FLOOR) return vec3(0.0);
  return vec3(sums[0].x + sums[1].x, sums[0].y, sums[1].y) / q;
}
vec3 cloth_integrand_split_widened(vec3 n, vec3 u, vec3 wi, vec3 wo, float widen2) {
  if (dot(n, wi) <= 0.0 || dot(n, wo) <= 0.0) return vec3(0.0);
  return cloth_integrand_split_view(cloth_view(n, u, wo), wi, widen2);
}
vec3 cloth_integrand_split(vec3 n, vec3 u, vec3 wi, vec3 wo) { return cloth_integrand_split_widened(n, u, wi, wo, 0.0); }
// The integrand in colour, each lobe widened by `widen2` (0: ClothBsdf::Point::integrand itself).
vec3 cloth_integrand_widened(vec3 n, vec3 u, vec3 wi, vec3 wo, float widen2) {
  vec3 s = cloth_integrand_split_widened(n, u, wi, wo, widen2);
  return vec3(s.x) + s.y * u_threads[0].albedo + s.z * u_threads[1].albedo;
}

// Σ_j ⟨f_s · W · cos θ_i⟩_j for the frame (n, u, v = n × u): ClothBsdf::Point::integrand.
vec3 cloth_integrand(vec3 n, vec3 u, vec3 wi, vec3 wo) { return cloth_integrand_widened(n, u, wi, wo, 0.0); }
