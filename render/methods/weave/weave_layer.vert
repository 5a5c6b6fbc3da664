// The weave layer's mesh with its weave coordinates. With WEAVE_VERTEX_TERMS, each vertex's fabric-level
// response (weave_vertex_pass.frag) and per-float table (weave_table_pass.frag), read by
// gl_VertexID and interpolated; without, its position, frame and visibility of every light
// (weave_visibility.glsl), from which weave_layer.frag computes the terms per pixel, and with
// WEAVE_VERTEX_LEVEL besides those the per-vertex fabric-level response alone.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_warp;
layout(location = 4) in vec3 a_st;  // the weave's coordinates (s, t, 0): scene/weave_scale.h
uniform mat4 u_view_projection;
out highp vec2 v_st;
#if defined(WEAVE_VERTEX_TERMS) || defined(WEAVE_VERTEX_LEVEL)
uniform highp sampler2D u_vertex_radiance;
uniform int u_vertex_width;
uniform int u_vertex_rows;
out vec3 v_fabric;
#endif
#ifdef WEAVE_VERTEX_TERMS
uniform highp sampler2D u_weave_table;
out vec4 v_table[WEAVE_TABLE_VEC4S];  // the table's RGB values packed, so the GL's fewest varyings hold it
#else
out vec3 v_position;
out vec3 v_normal;
out vec3 v_warp;
out vec4 v_visibility[Q_GROUPS];
#endif
invariant gl_Position;  // as visible_vertices.vert's, which marks the vertices this draw shows
void main() {
#if defined(WEAVE_VERTEX_TERMS) || defined(WEAVE_VERTEX_LEVEL)
  ivec2 texel = ivec2(gl_VertexID % u_vertex_width, gl_VertexID / u_vertex_width);
  v_fabric = texelFetch(u_vertex_radiance, texel, 0).rgb;
#endif
#ifdef WEAVE_VERTEX_TERMS
  for (int k = 0; k < WEAVE_TABLE_NODES; ++k) {
    vec3 node = texelFetch(u_weave_table, texel + ivec2(0, k * u_vertex_rows), 0).rgb;
    for (int c = 0; c < 3; ++c) v_table[(3 * k + c) / 4][(3 * k + c) % 4] = node[c];
  }
#else
  for (int g = 0; g < Q_GROUPS; ++g) v_visibility[g] = weave_visibility(gl_VertexID, g);
#endif
#ifndef WEAVE_VERTEX_TERMS
  v_position = a_position;
  v_normal = a_normal;
  v_warp = a_warp;
#endif
  v_st = a_st.xy;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
