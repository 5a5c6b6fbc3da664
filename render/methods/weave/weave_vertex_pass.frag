// The weave layer, step 1 (methods/iwasaki/vertex_pass.h): at every mesh vertex, block 0 the
// fabric-level response to the SGs as point lights, Σ_k P_k·integrand(ξ_k, ω_o), and blocks
// 1 … Q_GROUPS each SG's Q(ξ_k, ω_o), four to a texel. Needs microcylinder.glsl,
// vertex_pass.glsl and weave_ratio.glsl (its SG uniforms) before it.
uniform vec3 u_eye;
out vec4 o_value;
void main() {
  PassTexel t = pass_texel();
  if (pass_keeps(t)) discard;  // no visible triangle uses it
  if (t.i >= u_vertex_count || t.k > Q_GROUPS) {
    o_value = vec4(0.0);
    return;
  }
  vec3 p = texelFetch(u_vertex_position, t.p, 0).xyz;
  vec3 n = normalize(texelFetch(u_vertex_normal, t.p, 0).xyz);
  vec3 warp = texelFetch(u_vertex_warp, t.p, 0).xyz;
  vec3 wo = normalize(u_eye - p);
  if (dot(n, wo) < 0.0) n = -n;  // two-sided: the side facing the eye
  vec3 u = normalize(warp - dot(warp, n) * n);
  if (t.k == 0) {
    vec3 fabric = vec3(0.0);
    for (int k = 0; k < u_sg_count; ++k) fabric += u_sg_power[k] * cloth_integrand_widened(n, u, u_sg_axis[k], wo, u_sg_widen2[k]);
    o_value = vec4(fabric, 1.0);
    return;
  }
  vec4 q = vec4(0.0);
  for (int c = 0; c < 4; ++c) {
    int k = 4 * (t.k - 1) + c;
    if (k < u_sg_count) q[c] = cloth_q(n, u, u_sg_axis[k], wo);
  }
  o_value = q;
}
