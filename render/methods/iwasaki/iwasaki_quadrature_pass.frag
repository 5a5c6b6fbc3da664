// Methods `iwasaki_vertex_quadrature` and `iwasaki_quadrature`, the per-vertex pass
// (methods/vertex_pass/vertex_pass.h): at every mesh vertex the broad lobes' quadrature
// (broad_lobe_quadrature.glsl), split as (surface, warp volume, weft volume) per unit albedo so that
// the albedo (a knob, a texture's texel) applies per pixel. With u_pass_narrow
// (iwasaki_vertex_quadrature) one fragment per (vertex, SG k) in row block k, as
// iwasaki_vertex_pass.frag: SG k's split at unit amplitude, its quadrature if it is broad, else
// iwasaki's with the vertex's own SDF values (iwasaki_vertex.frag applies the amplitudes and the
// facet's cut). Without (iwasaki_quadrature, which shades the other SGs per pixel), three blocks:
// block b holds Σ over the broad SGs of μ_k times part b of the split (iwasaki_quadrature.frag).
uniform bool u_pass_narrow;
out vec4 o_radiance;
void main() {
  PassTexel t = pass_texel();
  int i = t.i, k = t.k;
  if (pass_keeps_turn(t, u_eye)) discard;  // no visible triangle uses it, or it is not its turn
  if (t.past || (u_pass_narrow ? k >= u_sg_count : k >= 3)) {
    o_radiance = vec4(0.0);
    return;
  }
  vec3 position = texelFetch(u_vertex_position, t.p, 0).xyz, normal = texelFetch(u_vertex_normal, t.p, 0).xyz,
       warp = texelFetch(u_vertex_warp, t.p, 0).xyz;
  vec3 value;
  if (!u_pass_narrow) {
    value = vec3(0.0);
    for (int g = 0; g < u_sg_count; ++g)
      if (u_sg_broad[g] != 0) value += u_sg_amplitude[g] * broad_lobe_split(i, position, normal, warp, g)[k];
  } else if (u_sg_broad[k] != 0) {
    value = broad_lobe_split(i, position, normal, warp, k);
  } else {
    value = iwasaki_sg_split(position, normal, warp, ivec3(i), vec3(1.0, 0.0, 0.0), k);
  }
  o_radiance = vec4(value, u_pass_time);
}
