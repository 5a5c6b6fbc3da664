// Methods `iwasaki_vertex_quadrature` and `iwasaki_quadrature`, the per-vertex pass
// (methods/iwasaki/vertex_pass.h): at every mesh vertex the broad lobes' quadrature
// (broad_lobe_quadrature.glsl). With u_pass_narrow (iwasaki_vertex_quadrature) one fragment per
// (vertex, SG k) in row block k, as iwasaki_vertex_pass.frag: SG k's quadrature if it is broad, else
// iwasaki for SG k with the vertex's own SDF values (iwasaki_vertex.frag cuts those by the facet's
// plane). Without (iwasaki_quadrature, which shades the other SGs per pixel), one block: every broad
// SG's quadrature summed.
uniform bool u_pass_narrow;
out vec4 o_radiance;
void main() {
  PassTexel t = pass_texel();
  int i = t.i, k = t.k;
  if (i >= u_vertex_count || (u_pass_narrow && k >= u_sg_count)) {
    o_radiance = vec4(0.0);
    return;
  }
  vec3 position = texelFetch(u_vertex_position, t.p, 0).xyz, normal = texelFetch(u_vertex_normal, t.p, 0).xyz,
       warp = texelFetch(u_vertex_warp, t.p, 0).xyz;
  vec3 radiance;
  if (!u_pass_narrow)
    radiance = broad_lobe_radiance(i, position, normal, warp, 0, u_sg_count);
  else if (u_sg_broad[k] != 0)
    radiance = broad_lobe_radiance(i, position, normal, warp, k, k + 1);
  else
    radiance = iwasaki_sg_radiance(position, normal, warp, ivec3(i), vec3(1.0, 0.0, 0.0), k, k + 1);
  o_radiance = vec4(radiance, 1.0);
}
