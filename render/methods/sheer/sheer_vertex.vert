// Method `sheer_vertex`, step 2: the per-vertex source and alpha of sheer_vertex_pass.frag,
// interpolated across each triangle (as iwasaki_vertex.vert does with radiance).
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
uniform highp sampler2D u_vertex_radiance;
uniform int u_vertex_width;
out vec4 v_source;
void main() {
  v_source = texelFetch(u_vertex_radiance, ivec2(gl_VertexID % u_vertex_width, gl_VertexID / u_vertex_width), 0);
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
