// Methods `iwasaki_vertex`, `iwasaki_vertex_mask`, `iwasaki_vertex_quadrature`, step 3: the sum over
// SGs of each one's interpolated split (surface, warp volume, weft volume) times its amplitude μ_k,
// cut by the facet's plane (facet_horizon.glsl, as the per-pixel rungs do: the reference's shadow
// rays start from the flat triangle), at the interpolated shading normal facing the eye; then
// surface + A_warp·t_warp(uv)·(warp volume) + A_weft·t_weft(uv)·(weft volume) with the threads'
// albedos (knobs) and a texture's texels (thread_maps.glsl). A broad SG's quadrature
// (u_sg_broad ≠ 0) is summed as it is: its mask bits hold the horizon. Needs erf.glsl,
// sg_lighting.glsl, facet_horizon.glsl and thread_maps.glsl before it; C++ twin: iwasaki.h's
// facet_interpolated_radiance.
uniform vec3 u_eye;
uniform vec3 u_sg_hemisphere_terms[MAX_SGS];  // sg_hemisphere_terms(λ_k), once per draw
uniform vec3 u_thread_albedo[2];              // A of the warp and the weft (the knobs' colour)
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_sg_surface[SG_GROUPS];
in vec4 v_sg_warp[SG_GROUPS];
in vec4 v_sg_weft[SG_GROUPS];
out vec4 o_radiance;
void main() {
  vec3 ns = normalize(v_normal);
  if (dot(ns, u_eye - v_position) < 0.0) ns = -ns;
  vec3 ng = facet_normal(v_position, u_eye);
  vec3 surface = vec3(0.0), warp = vec3(0.0), weft = vec3(0.0);
  for (int g = 0; g < SG_GROUPS; ++g) {
    for (int c = 0; c < 4; ++c) {
      int k = 4 * g + c;
      if (k >= u_sg_count) break;
      float f = u_sg_broad[k] != 0 ? 1.0 : facet_horizon_factor_terms(u_sg_hemisphere_terms[k], u_sg_axis[k], ns, ng);
      vec3 mu = u_sg_amplitude[k] * f;
      surface += mu * v_sg_surface[g][c];
      warp += mu * v_sg_warp[g][c];
      weft += mu * v_sg_weft[g][c];
    }
  }
  o_radiance = vec4(surface + u_thread_albedo[0] * thread_tint(0, v_uv) * warp + u_thread_albedo[1] * thread_tint(1, v_uv) * weft,
                    1.0);
}
