// Method `sheen`: Lambert + Charlie sheen (Estevez & Kulla) with Neubelt visibility, lit by
// the SGs. Mirrors methods/sheen/sheen.cpp; needs sg_lighting.glsl.
uniform vec3 u_sheen_thread_diffuse[2];  // SheenParams::thread_diffuse: w_j·A_j
uniform vec3 u_sheen_colour;
uniform float u_sheen_roughness;  // α

float charlie_distribution(float alpha, float n_dot_h) {
  float inv = 1.0 / alpha;
  float sin2 = max(1.0 - n_dot_h * n_dot_h, 0.0078125);
  return (2.0 + inv) * pow(sin2, 0.5 * inv) / (2.0 * SG_PI);
}
float neubelt_visibility(float nl, float nv) { return 1.0 / (4.0 * (nl + nv - nl * nv)); }

// The Lambert reflectance with thread j's part times tint_j (a texture's texel; 1 untextured):
// sheen_tinted(p, tint).diffuse.
vec3 sheen_diffuse(vec3 tint0, vec3 tint1) {
  return u_sheen_thread_diffuse[0] * tint0 + u_sheen_thread_diffuse[1] * tint1;
}

vec3 sheen_brdf(vec3 diffuse, vec3 n, vec3 wi, vec3 wo) {
  float nl = dot(n, wi), nv = dot(n, wo);
  if (nl <= 0.0 || nv <= 0.0) return vec3(0.0);
  vec3 h = normalize(wi + wo);
  float nh = clamp(dot(n, h), 0.0, 1.0);
  return diffuse / SG_PI +
         u_sheen_colour * (charlie_distribution(u_sheen_roughness, nh) * neubelt_visibility(nl, nv));
}
vec3 sheen_radiance(vec3 n, vec3 wo, vec3 diffuse) {
  if (dot(n, wo) <= 0.0) return vec3(0.0);
  vec3 l = vec3(0.0);
  for (int k = 0; k < u_sg_count; ++k) l += sg_irradiance(k, n) * sheen_brdf(diffuse, n, lift_above_horizon(u_sg_axis[k], n), wo);
  return l;
}
