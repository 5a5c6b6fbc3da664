// The weave layer's factor per pixel: the fabric-level terms (weave_terms) at the pixel, or with
// WEAVE_VERTEX_TERMS interpolated from the vertices as a per-vertex method's shading is, each
// light weighted by its visibility interpolated from the vertices (weave_weights), then
// weave_ratio_filtered() over the pixel's footprint,
// eased to 1 (the fabric-level shading) as the pixel's footprint grows from u_lod.x to u_lod.y
// threads, so a distant cloth is the fabric-level method's, untouched. Drawn over the cloth
// with multiplicative blending. Needs microcylinder.glsl, weave_layout.glsl, weave_ratio.glsl.
uniform vec3 u_eye;
uniform highp vec2 u_tiles_per_uv;
uniform vec2 u_lod;
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in highp vec2 v_uv;
#ifdef WEAVE_VERTEX_TERMS
in vec3 v_fabric;
in vec4 v_q[Q_GROUPS];
#endif
in vec4 v_visibility[Q_GROUPS];
out vec4 o_factor;
void main() {
  highp vec2 st = v_uv * u_tiles_per_uv;
  highp vec2 dx = dFdx(st), dy = dFdy(st);
  float footprint = max(length(dx), length(dy)) * float(u_weave_rows);  // in threads: weave_thread_footprint
  float coarse = smoothstep(u_lod.x, u_lod.y, footprint);
  if (coarse >= 1.0) {
    o_factor = vec4(1.0);
    return;
  }
  vec3 n = normalize(v_normal);
  vec3 wo = normalize(u_eye - v_position);
  if (dot(n, wo) < 0.0) n = -n;
  vec3 u = normalize(v_warp - dot(v_warp, n) * n);
  vec3 fabric;
  vec4 q[Q_GROUPS], weight[Q_GROUPS];
#ifdef WEAVE_VERTEX_TERMS
  fabric = v_fabric;
  for (int g = 0; g < Q_GROUPS; ++g) q[g] = v_q[g];
#else
  weave_terms(n, u, wo, v_visibility, fabric, q);
#endif
  weave_weights(v_visibility, q, weight);
  o_factor = vec4(mix(weave_ratio_filtered(n, u, wo, st, dx, dy, fabric, weight), vec3(1.0), coarse), 1.0);
}
