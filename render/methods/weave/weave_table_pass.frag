// The weave layer's per-float table per vertex (weave_float_table.glsl), for a method that shades
// per vertex: block k = j·WEAVE_TABLE_ARCS + m holds thread j's node m at every mesh vertex, from
// the vertex's Q (weave_vertex_pass.frag's blocks, u_weave_terms) and visibility. Needs
// microcylinder.glsl, vertex_pass.glsl, erf.glsl, weave_layout.glsl, weave_ratio.glsl,
// weave_visibility.glsl, weave_reach.glsl and weave_float_table.glsl before it.
uniform vec3 u_eye;
uniform highp sampler2D u_weave_terms;
out vec4 o_value;
void main() {
  PassTexel t = pass_texel();
  if (weave_vertex_unresolved(t.m)) discard;  // no pixel near it shows the weave
  // Kept where no visible triangle uses it or another share is due; computed where it was out of reach.
  if (!weave_vertex_newly_resolved(t.m) && pass_keeps(t)) discard;
  vec3 p = texelFetch(u_vertex_position, t.p, 0).xyz;
  if (t.past || t.k >= WEAVE_TABLE_NODES) {
    o_value = vec4(0.0);
    return;
  }
  vec3 n = normalize(texelFetch(u_vertex_normal, t.p, 0).xyz);
  vec3 warp = texelFetch(u_vertex_warp, t.p, 0).xyz;
  vec3 wo = normalize(u_eye - p);
  if (dot(n, wo) < 0.0) n = -n;  // two-sided: the side facing the eye
  vec3 u = normalize(warp - dot(warp, n) * n);
  vec4 vis[Q_GROUPS], q[Q_GROUPS], weight[Q_GROUPS];
  for (int g = 0; g < Q_GROUPS; ++g) {
    vis[g] = weave_visibility(t.i, g);
    q[g] = texelFetch(u_weave_terms, t.m + ivec2(0, (g + 1) * u_vertex_mesh_rows), 0);  // the terms' result
  }
  weave_weights(vis, q, weight);
  int j = t.k / WEAVE_TABLE_ARCS;
  o_value = vec4(weave_table_node(n, u, wo, j, t.k - j * WEAVE_TABLE_ARCS, weight), 1.0);
}
