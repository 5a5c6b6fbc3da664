// Methods `iwasaki_vertex` and `iwasaki_vertex_mask`, step 1 (methods/iwasaki/vertex_pass.h): seed 000
// (iwasaki.glsl) at every mesh vertex and SG, one fragment per (vertex i, SG k) at texel
// (i mod W, i div W + k·rows), with the vertex's own SDF values (weight 1). iwasaki_vertex.vert then
// reads the vertex's SGs by gl_VertexID, and iwasaki_vertex.frag cuts each by the facet's plane.
uniform highp sampler2D u_vertex_position;
uniform highp sampler2D u_vertex_normal;
uniform highp sampler2D u_vertex_warp;
uniform int u_vertex_width;
uniform int u_vertex_rows;
uniform int u_vertex_count;
out vec4 o_radiance;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int k = p.y / u_vertex_rows;
  p.y -= k * u_vertex_rows;
  int i = p.y * u_vertex_width + p.x;
  if (i >= u_vertex_count || k >= u_sg_count) {
    o_radiance = vec4(0.0);
    return;
  }
  o_radiance = vec4(iwasaki_sg_radiance(texelFetch(u_vertex_position, p, 0).xyz, texelFetch(u_vertex_normal, p, 0).xyz,
                                        texelFetch(u_vertex_warp, p, 0).xyz, ivec3(i), vec3(1.0, 0.0, 0.0), k, k + 1),
                    1.0);
}
