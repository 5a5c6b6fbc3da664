// `thin`'s reflection by sgpoint: each SG as a directional light of its whole power, full
// model (needs microcylinder.glsl and sg_lighting.glsl). Mirrors methods/sgpoint/sgpoint.cpp.
vec3 thin_reflection(vec3 n, vec3 u, vec3 wo) {
  vec3 l = vec3(0.0);
  for (int k = 0; k < u_sg_count; ++k) l += sg_power(k) * cloth_integrand(n, u, u_sg_axis[k], wo);
  return l;
}
// sgpoint has no visibility: every SG reaches both sides whole.
vec2 thin_light_visibility(int k, vec3 n) { return vec2(1.0); }
