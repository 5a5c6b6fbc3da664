// SG lighting for the SG-lit methods (sheen, mdfrot, thin): the SGs as uniforms, their
// clamped-cosine irradiance (core/spherical_gaussian.cpp's Tokuyoshi 2024 fit, term by term)
// and the horizon lift of methods/sg_lights.cpp. Parity: tests/gpu/method_parity_test.cpp.
// Needs erf.glsl before it.
#define SG_LIGHTING_GLSL  // iwasaki.glsl then leaves out the SG uniforms it shares with this file
#define MAX_SGS 40
uniform int u_sg_count;
uniform vec3 u_sg_axis[MAX_SGS];
uniform float u_sg_sharpness[MAX_SGS];
uniform vec3 u_sg_amplitude[MAX_SGS];
// 0: the method shades SG k itself; s + 1: the broad-lobe quadrature does, in slot s
// (methods/iwasaki/broad_lobe_quadrature.h's broad_lobe_slots).
uniform int u_sg_broad[MAX_SGS];

const float SG_PI = 3.14159265358979;
const float SG_HORIZON_COSINE = 0.02;  // kSgHorizonCosine

float sg_expm1(float x) { return abs(x) < 1e-3 ? x * (1.0 + 0.5 * x) : exp(x) - 1.0; }
float sg_one_minus_exp_over(float x) { return x == 0.0 ? 1.0 : -sg_expm1(-x) / x; }

float sg_upper_cosine_over_two_pi(float lambda) {
  if (lambda >= 0.5) return (1.0 - sg_one_minus_exp_over(lambda)) / lambda;
  float term = 0.5, sum = 0.0;
  for (int j = 0; j < 20; ++j) { sum += term; term *= -lambda / float(j + 3); }
  return sum;
}
float sg_lower_cosine_over_two_pi(float lambda) {
  float e = exp(-lambda);
  if (lambda >= 0.5) return e * (sg_one_minus_exp_over(lambda) - e) / lambda;
  float power = 1.0, sum = 0.0;
  for (int k = 0; k < 20; ++k) { sum += power / float(k + 2); power *= -lambda / float(k + 1); }
  return e * sum;
}
// ∫ exp(λ(ω·ξ−1)) max(ω·n, 0) dω with c = ξ·n.
float sg_clamped_cosine_integral(float lambda, float c) {
  c = clamp(c, -1.0, 1.0);
  float upper = sg_upper_cosine_over_two_pi(lambda);
  float lower = sg_lower_cosine_over_two_pi(lambda);
  const float A = 2.7360831611272558, B = 17.021297781741875, C = 4.0100826728510421,
              D = 15.219156263147211, E = 76.087896272360737;
  float t = lambda * sqrt(0.5 * ((lambda + A) * lambda + B) / (((lambda + C) * lambda + D) * lambda + E));
  float factor = 0.5 + 0.5 * c;
  if (t >= 1e-6) {
    float tc = t * c;
    factor = 0.5 * (c * erfc_nr(-tc) + erfc_nr(t)) -
             0.5 / sqrt(SG_PI) * exp(-tc * tc) * sg_expm1(t * t * (c * c - 1.0)) / t;
  }
  return 2.0 * SG_PI * (lower + (upper - lower) * factor);
}
// ∫_{ω·n>0} exp(λ(ω·ξ−1)) dω (Tokuyoshi 2022's fit, as core's sg_hemisphere_integral).
float sg_hemisphere_integral(float lambda, float c) {
  c = clamp(c, -1.0, 1.0);
  float upper = 2.0 * SG_PI * sg_one_minus_exp_over(lambda);
  float lower = exp(-lambda) * upper;
  const float A = 0.6517328826907056, B = 1.3418280033141288, C = 7.2216687798956709;
  float t = lambda * sqrt((0.5 * lambda + A) / ((lambda + B) * lambda + C));
  float factor = t < 1e-6 ? 0.5 + 0.5 * c : 0.5 + 0.5 * (1.0 - erfc_nr(t * c)) / (1.0 - erfc_nr(t));
  return lower + (upper - lower) * factor;
}
// E/H clamped to [SG_HORIZON_COSINE, 1]: methods/sg_lights.cpp's sg_effective_cosine.
float sg_effective_cosine(float lambda, float c) {
  float h = sg_hemisphere_integral(lambda, c);
  if (!(h > 0.0)) return SG_HORIZON_COSINE;
  return clamp(sg_clamped_cosine_integral(lambda, c) / h, SG_HORIZON_COSINE, 1.0);
}
vec3 sg_irradiance(int k, vec3 n) {
  return u_sg_amplitude[k] * sg_clamped_cosine_integral(u_sg_sharpness[k], dot(u_sg_axis[k], n));
}
// ∫ G_k dω: sgpoint's light power.
vec3 sg_power(int k) {
  float l = u_sg_sharpness[k];
  return u_sg_amplitude[k] * (4.0 * SG_PI * sg_one_minus_exp_over(2.0 * l));
}
// axis moved along the great circle through n until n·axis ≥ h (unchanged when already there).
vec3 lift_to_cosine(vec3 axis, vec3 n, float h) {
  float c = dot(axis, n);
  if (c >= h) return axis;
  vec3 t = axis - c * n;
  float len = length(t);
  if (len < 1e-6) {
    t = abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0));
    len = length(t);
  }
  return t / len * sqrt(1.0 - h * h) + h * n;
}
vec3 lift_above_horizon(vec3 axis, vec3 n) { return lift_to_cosine(axis, n, SG_HORIZON_COSINE); }

// core's SgWarpedGrid: an n × 2n midpoint grid in (u, φ) in the SG's frame, cos θ = 1 + ln(1 −
// u(1 − e^{−2λ}))/λ, so every cell holds ∫exp(λ(ω·ξ − 1))dω/(2n²) (sg_grid_cell_weight).
float sg_grid_polar_cosine(float lambda, int n, int i) {
  float u = (float(i) + 0.5) / float(n);
  return clamp(1.0 + log(1.0 + u * sg_expm1(-2.0 * lambda)) / lambda, -1.0, 1.0);
}
vec3 sg_grid_direction(vec3 axis, float cos_t, int n, int j) {
  vec3 x = normalize(abs(axis.x) < 0.9 ? cross(vec3(1.0, 0.0, 0.0), axis) : cross(vec3(0.0, 1.0, 0.0), axis));
  vec3 y = cross(axis, x);
  float sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
  float phi = 2.0 * SG_PI * (float(j) + 0.5) / float(2 * n);
  return sin_t * cos(phi) * x + sin_t * sin(phi) * y + cos_t * axis;
}
float sg_grid_cell_weight(float lambda, int n) {
  return 2.0 * SG_PI * sg_one_minus_exp_over(2.0 * lambda) * 2.0 / float(2 * n * n);
}
