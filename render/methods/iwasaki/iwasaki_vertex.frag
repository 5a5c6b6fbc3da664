// Methods `iwasaki_vertex`, `iwasaki_vertex_mask`, `iwasaki_vertex_quadrature`, step 3: the sum over
// SGs of each one's interpolated split (surface, warp volume, weft volume) times its amplitude μ_k,
// cut by the facet's plane (facet_horizon.glsl, as the per-pixel rungs do: the reference's shadow
// rays start from the flat triangle), at the interpolated shading normal facing the eye; then
// surface + A_warp·t_warp(uv)·(warp volume) + A_weft·t_weft(uv)·(weft volume) with the threads'
// albedos (knobs) and a texture's texels (thread_maps.glsl). A broad SG's quadrature
// (u_sg_broad ≠ 0) is summed as it is: its mask bits hold the horizon. Where a normal map's texel
// tilts, each sharp SG's parts (λ ≥ BROAD_LOBE_SHARPNESS) are multiplied by vertex_normal_map.glsl's
// ratio: the model's (normal_map_lobe_ratio) for the two SGs that light the pixel most, the
// clamped cosine's (normal_map_cosine_ratio) for the others, which is what keeps the cost per
// pixel near two SGs' model whatever the SG count. Needs microcylinder.glsl, erf.glsl,
// sg_lighting.glsl, facet_horizon.glsl, thread_maps.glsl, normal_map_frame.glsl,
// cloth_normal_map.glsl and vertex_normal_map.glsl before it; C++ twin: iwasaki.h's
// facet_interpolated_radiance, with a normal map vertex_normal_map.h's normal_mapped_facet_radiance.
uniform vec3 u_eye;
uniform vec3 u_sg_hemisphere_terms[MAX_SGS];  // sg_hemisphere_terms(λ_k), once per draw
uniform vec3 u_thread_albedo[2];              // A of the warp and the weft (the knobs' colour)
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in vec2 v_uv;
in vec4 v_sg_surface[SG_GROUPS];
in vec4 v_sg_warp[SG_GROUPS];
in vec4 v_sg_weft[SG_GROUPS];
out vec4 o_radiance;
void main() {
  vec3 ns = normalize(v_normal);
  if (dot(ns, u_eye - v_position) < 0.0) ns = -ns;
  vec3 ng = facet_normal(v_position, u_eye);
  vec3 tint0 = u_thread_albedo[0] * thread_tint(0, v_uv), tint1 = u_thread_albedo[1] * thread_tint(1, v_uv);
#if !NORMAL_MAPPED
  // No map on this object: each SG's cut applied as it is summed, none of the ratio's code
  // (IwasakiCloth::facet_draw says why).
  vec3 surface = vec3(0.0), warp = vec3(0.0), weft = vec3(0.0);
  for (int g = 0; g < SG_GROUPS; ++g) {
    for (int c = 0; c < 4; ++c) {
      int k = 4 * g + c;
      if (k >= u_sg_count) break;
      float cut = u_sg_broad[k] != 0 ? 1.0 : facet_horizon_factor_terms(u_sg_hemisphere_terms[k], u_sg_axis[k], ns, ng);
      vec3 mu = u_sg_amplitude[k] * cut;
      surface += mu * v_sg_surface[g][c];
      warp += mu * v_sg_warp[g][c];
      weft += mu * v_sg_weft[g][c];
    }
  }
  o_radiance = vec4(surface + tint0 * warp + tint1 * weft, 1.0);
#else
  vec3 t = normal_map_at(v_uv);
  bool bumped = normal_map_tilts(t);
  // Each SG's cut by the facet; with a normal map, the two sharp SGs whose light here is largest
  // (the first of equals).
  float cut[4 * SG_GROUPS];
  int first = -1, second = -1;
  float light_first = -1.0, light_second = -1.0;
  for (int g = 0; g < SG_GROUPS; ++g) {
    for (int c = 0; c < 4; ++c) {
      int k = 4 * g + c;
      if (k >= u_sg_count) break;
      cut[k] = u_sg_broad[k] != 0 ? 1.0 : facet_horizon_factor_terms(u_sg_hemisphere_terms[k], u_sg_axis[k], ns, ng);
      if (!bumped || u_sg_broad[k] != 0 || u_sg_sharpness[k] < BROAD_LOBE_SHARPNESS) continue;
      vec3 mu = u_sg_amplitude[k] * cut[k];
      vec3 light = mu * v_sg_surface[g][c] + tint0 * (mu * v_sg_warp[g][c]) + tint1 * (mu * v_sg_weft[g][c]);
      float l = light.r + light.g + light.b;
      if (l > light_first) {
        second = first, light_second = light_first;
        first = k, light_first = l;
      } else if (l > light_second) {
        second = k, light_second = l;
      }
    }
  }
  // The model's ratio of those two, each evaluated once outside the SG loop: pixels processed
  // together (SIMD lanes, a GPU's warp) pick different SGs, and a call inside the loop would run
  // for every SG some lane picked.
  vec3 us = vec3(0.0), nb = ns, ub = vec3(0.0), wo = vec3(0.0), r_first = vec3(1.0), r_second = vec3(1.0);
  if (bumped) {
    us = normalize(v_warp - dot(v_warp, ns) * ns);
    ub = us;
    normal_mapped_frame(nb, ub, t);
    wo = normalize(u_eye - v_position);
    if (first >= 0)
      r_first = normal_map_lobe_ratio(ns, us, nb, ub, u_sg_axis[first], wo, u_sg_sharpness[first], u_sg_widen2[first]);
    if (second >= 0)
      r_second = normal_map_lobe_ratio(ns, us, nb, ub, u_sg_axis[second], wo, u_sg_sharpness[second], u_sg_widen2[second]);
  }
  vec3 surface = vec3(0.0), warp = vec3(0.0), weft = vec3(0.0);
  for (int g = 0; g < SG_GROUPS; ++g) {
    for (int c = 0; c < 4; ++c) {
      int k = 4 * g + c;
      if (k >= u_sg_count) break;
      vec3 mu = u_sg_amplitude[k] * cut[k];
      if (bumped && u_sg_broad[k] == 0 && u_sg_sharpness[k] >= BROAD_LOBE_SHARPNESS) {
        vec3 r = k == first    ? r_first
                 : k == second ? r_second
                               : normal_map_cosine_ratio(ns, nb, u_sg_axis[k], u_sg_sharpness[k]);
        surface += mu * v_sg_surface[g][c] * r.x;
        warp += mu * v_sg_warp[g][c] * r.y;
        weft += mu * v_sg_weft[g][c] * r.z;
        continue;
      }
      surface += mu * v_sg_surface[g][c];
      warp += mu * v_sg_warp[g][c];
      weft += mu * v_sg_weft[g][c];
    }
  }
  o_radiance = vec4(surface + tint0 * warp + tint1 * weft, 1.0);
#endif
}
