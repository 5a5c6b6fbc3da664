// Methods `iwasaki_vertex` and `iwasaki_vertex_mask`, step 1 (methods/vertex_pass/vertex_pass.h):
// iwasaki_sg_split (iwasaki.glsl) at every mesh vertex and SG, one fragment per (vertex i, SG k) at
// texel (i mod W, i div W + k·rows), with the vertex's own SDF values (weight 1): the SG's light at
// unit amplitude as (surface, warp volume, weft volume). iwasaki_vertex.vert then reads the vertex's
// SGs by gl_VertexID, and iwasaki_vertex.frag applies each SG's amplitude, the threads' albedos
// (times a texture's texels) and the facet's cut per pixel. The albedo is not in the pass: a colour
// knob does not recompute it.
out vec4 o_radiance;
void main() {
  PassTexel t = pass_texel();
  if (pass_keeps_turn(t, u_eye)) discard;  // no visible triangle uses it, or it is not its turn
  if (t.past || t.k >= u_sg_count) {
    o_radiance = vec4(0.0);
    return;
  }
  o_radiance = vec4(iwasaki_sg_split(texelFetch(u_vertex_position, t.p, 0).xyz, texelFetch(u_vertex_normal, t.p, 0).xyz,
                                     texelFetch(u_vertex_warp, t.p, 0).xyz, ivec3(t.i), vec3(1.0, 0.0, 0.0), t.k),
                    u_pass_time);
}
