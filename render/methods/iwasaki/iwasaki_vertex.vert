// Method `iwasaki_vertex`, step 2: seed 000's radiance at each mesh vertex, computed by the
// fragment pass iwasaki_vertex_pass.frag (texel (i mod W, i div W) for vertex i), interpolated
// across each triangle (Gouraud). Cheap where pixels far outnumber vertices; blurs what varies
// faster than the mesh (sharp highlights, shadow edges).
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
uniform highp sampler2D u_vertex_radiance;
uniform int u_vertex_width;
out vec3 v_radiance;
void main() {
  v_radiance = texelFetch(u_vertex_radiance, ivec2(gl_VertexID % u_vertex_width, gl_VertexID / u_vertex_width), 0).rgb;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
