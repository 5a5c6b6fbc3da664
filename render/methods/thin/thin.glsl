// Method `thin`: optically thin layer — alpha e^{−τ/μ}, single-scatter diffuse
// reflection/transmission from the SG irradiance on both sides, composed over a reflection
// method: the program links one definition of thin_reflection() and of thin_light_visibility()
// (thin_over_sgpoint.glsl for `thin`; methods/sheer/sheer.glsl for iwasaki with its visibility).
// Mirrors methods/thin/thin.cpp; needs sg_lighting.glsl.
// Radiance reflected by the cloth's own reflection method, n facing the viewer.
vec3 thin_reflection(vec3 n, vec3 u, vec3 wo);
// Share of SG k's light reaching the layer on n's side (x) and on the far side (y): thin.h's
// ThinSideVisibility.
vec2 thin_light_visibility(int k, vec3 n);

uniform float u_thin_tau;
uniform vec3 u_thin_albedo;

float thin_alpha(float mu) { return exp(-u_thin_tau / max(mu, 1e-4)); }
vec3 thin_reflection_kernel(float mu, float mu0) {
  mu = max(mu, 1e-4); mu0 = max(mu0, 1e-4);
  return u_thin_albedo / (4.0 * SG_PI) * (-sg_expm1(-u_thin_tau * (1.0 / mu + 1.0 / mu0)) / (mu + mu0));
}
vec3 thin_transmission_kernel(float mu, float mu0) {
  mu = max(mu, 1e-4); mu0 = max(mu0, 1e-4);
  float k;
  if (abs(mu - mu0) < 1e-3) {
    float m = 0.5 * (mu + mu0);
    k = u_thin_tau / (m * m) * exp(-u_thin_tau / m);
  } else {
    k = (exp(-u_thin_tau / mu) - exp(-u_thin_tau / mu0)) / (mu - mu0);
  }
  return u_thin_albedo / (4.0 * SG_PI) * k;
}
vec3 thin_scatter(vec3 n, vec3 wo) {
  float mu = dot(n, wo);
  if (mu <= 0.0) return vec3(0.0);
  vec3 l = vec3(0.0);
  for (int k = 0; k < u_sg_count; ++k) {
    vec2 v = thin_light_visibility(k, n);
    float c = dot(u_sg_axis[k], n);
    float mu_front = sg_effective_cosine(u_sg_sharpness[k], c), mu_back = sg_effective_cosine(u_sg_sharpness[k], -c);
    l += v.x * sg_irradiance(k, n) * thin_reflection_kernel(mu, mu_front);
    l += v.y * sg_irradiance(k, -n) * thin_transmission_kernel(mu, mu_back);
  }
  return l;
}
// Premultiplied source and alpha; n is turned to face the viewer here.
vec4 thin_radiance(vec3 n, vec3 u, vec3 wo) {
  if (dot(n, wo) < 0.0) n = -n;
  float a = thin_alpha(dot(n, wo));
  return vec4((1.0 - a) * thin_reflection(n, u, wo) + thin_scatter(n, wo), a);
}
