// Methods `iwasaki_vertex`, `iwasaki_vertex_mask`, `iwasaki_vertex_quadrature`, step 3: the sum over
// SGs of each one's interpolated radiance cut by the facet's plane (facet_horizon.glsl, as the
// per-pixel rungs do: the reference's shadow rays start from the flat triangle), at the
// interpolated shading normal facing the eye. A broad SG's quadrature (u_sg_broad ≠ 0) is summed
// as it is: its mask bits hold the horizon. Needs erf.glsl, sg_lighting.glsl and
// facet_horizon.glsl before it; C++ twin: iwasaki.h's facet_interpolated_radiance.
uniform vec3 u_eye;
uniform vec3 u_sg_hemisphere_terms[MAX_SGS];  // sg_hemisphere_terms(λ_k), once per draw
in vec3 v_position;
in vec3 v_normal;
in vec4 v_sg_red[SG_GROUPS];
in vec4 v_sg_green[SG_GROUPS];
in vec4 v_sg_blue[SG_GROUPS];
out vec4 o_radiance;
void main() {
  vec3 ns = normalize(v_normal);
  if (dot(ns, u_eye - v_position) < 0.0) ns = -ns;
  vec3 ng = facet_normal(v_position, u_eye);
  vec3 sum = vec3(0.0);
  for (int g = 0; g < SG_GROUPS; ++g) {
    vec4 f = vec4(0.0);
    for (int c = 0; c < 4; ++c) {
      int k = 4 * g + c;
      if (k >= u_sg_count) break;
      f[c] = u_sg_broad[k] != 0 ? 1.0 : facet_horizon_factor_terms(u_sg_hemisphere_terms[k], u_sg_axis[k], ns, ng);
    }
    sum += vec3(dot(v_sg_red[g], f), dot(v_sg_green[g], f), dot(v_sg_blue[g], f));
  }
  o_radiance = vec4(sum, 1.0);
}
