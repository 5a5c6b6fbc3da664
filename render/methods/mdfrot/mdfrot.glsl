// Method `mdfrot`: alternating Ashikhmin–Shirley anisotropy per thread,
// tangent-curve + cross-section yarn normals, approximate MDF rotation (Eq. 9–11), averaged
// over the weave repeat. Mirrors methods/mdfrot/mdfrot.cpp; needs sg_lighting.glsl.
#define MDF_MAX_SAMPLES 16
struct MdfThread {
  vec3 diffuse;     // R_d
  float f0;         // R_s
  float n_along;
  float n_across;
  float weight;     // w_j
  int samples;
};
uniform MdfThread u_mdf_threads[2];
uniform float u_mdf_tilts[2 * MDF_MAX_SAMPLES];
uniform float u_mdf_bulge;  // β

float mdf_pow5(float x) { return x * x * x * x * x; }
vec3 mdf_perturbed_normal(float alpha, float beta) {
  return normalize(vec3(-sin(alpha), sin(beta), cos(alpha) * cos(beta)));
}
vec3 mdf_rotate_half(vec3 nt, vec3 h) {  // Eq. 11
  return vec3(nt.z * h.x - nt.x * h.z, -nt.x * nt.y * h.x + (1.0 - nt.y * nt.y) * h.y + nt.y * nt.z * h.z, dot(nt, h));
}
vec3 mdf_thread_sample(MdfThread t, vec3 ht, float nl, float nv, float kh) {
  vec3 f = t.diffuse * (28.0 / (23.0 * SG_PI) * (1.0 - t.f0) * (1.0 - mdf_pow5(1.0 - 0.5 * nl)) *
                        (1.0 - mdf_pow5(1.0 - 0.5 * nv)));
  if (ht.z <= 0.0) return f;
  float xy = ht.x * ht.x + ht.y * ht.y;
  float e = xy > 1e-12 ? (t.n_along * ht.x * ht.x + t.n_across * ht.y * ht.y) / xy : t.n_along;
  float fresnel = t.f0 + (1.0 - t.f0) * mdf_pow5(1.0 - kh);
  float spec = sqrt((t.n_along + 1.0) * (t.n_across + 1.0)) / (8.0 * SG_PI) * pow(ht.z, e) /
               (max(kh, 1e-4) * max(nl, nv)) * fresnel;
  return f + vec3(spec);
}
vec3 mdfrot_brdf(vec3 n, vec3 u, vec3 wi, vec3 wo) {
  float nl = dot(n, wi), nv = dot(n, wo);
  if (nl <= 0.0 || nv <= 0.0) return vec3(0.0);
  vec3 v = cross(n, u);
  vec3 h = normalize(wi + wo);
  float kh = clamp(dot(wi, h), 0.0, 1.0);
  vec3 f = vec3(0.0);
  for (int j = 0; j < 2; ++j) {
    vec3 along = j == 0 ? u : v, across = j == 0 ? v : u;
    vec3 hl = vec3(dot(h, along), dot(h, across), dot(h, n));
    vec3 sum = vec3(0.0);
    int count = u_mdf_threads[j].samples;
    for (int k = 0; k < count; ++k) {
      float beta = (k % 2 == 0) ? u_mdf_bulge : -u_mdf_bulge;
      vec3 nt = mdf_perturbed_normal(u_mdf_tilts[j * MDF_MAX_SAMPLES + k], beta);
      sum += mdf_thread_sample(u_mdf_threads[j], mdf_rotate_half(nt, hl), nl, nv, kh);
    }
    f += u_mdf_threads[j].weight * sum / float(count);
  }
  return f;
}
vec3 mdfrot_radiance(vec3 n, vec3 u, vec3 wo) {
  if (dot(n, wo) <= 0.0) return vec3(0.0);
  vec3 l = vec3(0.0);
  for (int k = 0; k < u_sg_count; ++k) l += sg_irradiance(k, n) * mdfrot_brdf(n, u, lift_above_horizon(u_sg_axis[k], n), wo);
  return l;
}
