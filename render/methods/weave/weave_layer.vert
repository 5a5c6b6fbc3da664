// The weave layer's mesh with its UVs and each vertex's visibility of every light
// (weave_visibility.glsl). With WEAVE_VERTEX_TERMS, also each vertex's fabric-level response and
// per-light Q from the vertex pass (weave_vertex_pass.frag), read by gl_VertexID and interpolated;
// without, weave_layer.frag computes them per pixel.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_warp;
layout(location = 4) in vec3 a_uv;  // (u, v, 0)
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_warp;
out highp vec2 v_uv;
#ifdef WEAVE_VERTEX_TERMS
uniform highp sampler2D u_vertex_radiance;
uniform int u_vertex_width;
uniform int u_vertex_rows;
out vec3 v_fabric;
out vec4 v_q[Q_GROUPS];
#endif
out vec4 v_visibility[Q_GROUPS];
invariant gl_Position;  // as visible_vertices.vert's, which marks the vertices this draw shows
void main() {
#ifdef WEAVE_VERTEX_TERMS
  ivec2 texel = ivec2(gl_VertexID % u_vertex_width, gl_VertexID / u_vertex_width);
  v_fabric = texelFetch(u_vertex_radiance, texel, 0).rgb;
  for (int g = 0; g < Q_GROUPS; ++g) v_q[g] = texelFetch(u_vertex_radiance, texel + ivec2(0, (g + 1) * u_vertex_rows), 0);
#endif
  for (int g = 0; g < Q_GROUPS; ++g) v_visibility[g] = weave_visibility(gl_VertexID, g);
  v_position = a_position;
  v_normal = a_normal;
  v_warp = a_warp;
  v_uv = a_uv.xy;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
