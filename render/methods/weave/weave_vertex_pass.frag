// The weave layer's terms per vertex (methods/vertex_pass/vertex_pass.h), for a method that shades per
// vertex: at every mesh vertex, block 0 the fabric-level response to the SGs as point lights and
// blocks 1 … Q_GROUPS each light's Q, four to a texel (weave_terms, with the vertex's
// weave_visibility). The layer's vertex shader
// interpolates them as the method interpolates its own shading, so the factor's ratio takes the
// method's interpolation out with it. Needs microcylinder.glsl, vertex_pass.glsl,
// weave_layout.glsl, weave_ratio.glsl, weave_visibility.glsl and weave_reach.glsl before it.
uniform vec3 u_eye;
out vec4 o_value;
void main() {
  PassTexel t = pass_texel();
  if (weave_vertex_unresolved(t.m)) discard;  // no pixel near it shows the weave
  // Kept where no visible triangle uses it or another share is due; computed where it was out of reach.
  if (!weave_vertex_newly_resolved(t.m) && pass_keeps(t)) discard;
  vec3 p = texelFetch(u_vertex_position, t.p, 0).xyz;
  if (t.past || t.k > Q_GROUPS) {
    o_value = vec4(0.0);
    return;
  }
  vec3 n = normalize(texelFetch(u_vertex_normal, t.p, 0).xyz);
  vec3 warp = texelFetch(u_vertex_warp, t.p, 0).xyz;
  vec3 wo = normalize(u_eye - p);
  if (dot(n, wo) < 0.0) n = -n;  // two-sided: the side facing the eye
  vec3 u = normalize(warp - dot(warp, n) * n);
  if (t.k > 0) {  // a group's Qs alone: the projection terms of its four lights
    o_value = weave_q_group(n, u, wo, t.k - 1);
    return;
  }
  vec3 fabric;
  vec4 vis[Q_GROUPS], q[Q_GROUPS];
  for (int g = 0; g < Q_GROUPS; ++g) vis[g] = weave_visibility(t.i, g);
  weave_terms(n, u, wo, vis, fabric, q);
  o_value = vec4(fabric, 1.0);
}
