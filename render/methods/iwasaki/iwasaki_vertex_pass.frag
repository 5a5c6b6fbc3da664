// Method `iwasaki_vertex`, step 1 (methods/iwasaki/vertex_pass.h): seed 000 (iwasaki.glsl) at every mesh
// vertex, one fragment per vertex i at texel (i mod W, i div W), with the vertex's own SDF values
// (weight 1). iwasaki_vertex.vert then reads the result by gl_VertexID.
uniform highp sampler2D u_vertex_position;
uniform highp sampler2D u_vertex_normal;
uniform highp sampler2D u_vertex_warp;
uniform int u_vertex_width;
uniform int u_vertex_count;
out vec4 o_radiance;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int i = p.y * u_vertex_width + p.x;
  if (i >= u_vertex_count) {
    o_radiance = vec4(0.0);
    return;
  }
  o_radiance = vec4(iwasaki_radiance(texelFetch(u_vertex_position, p, 0).xyz, texelFetch(u_vertex_normal, p, 0).xyz,
                                     texelFetch(u_vertex_warp, p, 0).xyz, ivec3(i), vec3(1.0, 0.0, 0.0)),
                    1.0);
}
