// The weave layer's factor per pixel: the fabric-level terms (weave_terms) at the pixel, each
// light weighted by its visibility interpolated from the vertices (weave_weights), then
// weave_ratio_filtered() over the pixel's footprint; with WEAVE_VERTEX_LEVEL the same over the
// fabric-level response of a per-vertex method's vertex pass, interpolated as the method's
// shading is, so the factor also lifts that shading to the pixel's; or with WEAVE_VERTEX_TERMS the fabric-level
// response and the per-float table interpolated from the vertices as a per-vertex method's
// shading is, then weave_ratio_tabled() over the footprint (no light is visited per pixel);
// eased to 1 (the fabric-level shading) as the pixel's footprint grows from u_lod.x to u_lod.y
// threads, so a distant cloth is the fabric-level method's, untouched. Drawn over the cloth
// with multiplicative blending. Needs microcylinder.glsl, weave_layout.glsl, weave_ratio.glsl,
// weave_float_table.glsl.
uniform vec3 u_eye;
uniform vec2 u_lod;
in highp vec2 v_st;
#ifdef WEAVE_VERTEX_TERMS
in vec3 v_fabric;
in vec4 v_table[WEAVE_TABLE_VEC4S];
#else
#ifdef WEAVE_VERTEX_LEVEL
in vec3 v_fabric;
#endif
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in vec4 v_visibility[Q_GROUPS];
#endif
out vec4 o_factor;
void main() {
  highp vec2 st = v_st;
  highp vec2 dx = dFdx(st), dy = dFdy(st);
  float footprint = max(length(dx), length(dy)) * float(u_weave_rows);  // in threads: weave_thread_footprint
  float coarse = smoothstep(u_lod.x, u_lod.y, footprint);
  // UVs collapsed to a point or a line leave the threads no place: the fabric level, as the
  // resolved reference keeps there (weave_degenerate_uvs). A pixel's footprint 10⁵ times finer
  // than a thread, or 10⁴ times longer than wide, is one.
  float spread = abs(dx.x * dy.y - dx.y * dy.x), longest = max(dot(dx, dx), dot(dy, dy));
  if (footprint < 1e-5 || spread <= 1e-4 * longest) coarse = 1.0;
  if (coarse >= 1.0) {
    o_factor = vec4(1.0);
    return;
  }
#ifdef WEAVE_VERTEX_TERMS
  vec3 table[WEAVE_TABLE_NODES];
  for (int k = 0; k < WEAVE_TABLE_NODES; ++k)
    for (int c = 0; c < 3; ++c) table[k][c] = v_table[(3 * k + c) / 4][(3 * k + c) % 4];
  o_factor = vec4(mix(weave_ratio_tabled(st, dx, dy, v_fabric, table), vec3(1.0), coarse), 1.0);
#else
  vec3 n = normalize(v_normal);
  vec3 wo = normalize(u_eye - v_position);
  if (dot(n, wo) < 0.0) n = -n;
  vec3 u = normalize(v_warp - dot(v_warp, n) * n);
#ifdef WEAVE_VERTEX_LEVEL
  // The level the per-vertex method drew, interpolated as it was, so that the factor lifts it to
  // the pixel's resolved shading. The lights' Qs per pixel: they follow the view too fast to interpolate.
  vec3 fabric = v_fabric;
  vec4 q[Q_GROUPS], weight[Q_GROUPS];
  weave_qs(n, u, wo, q);
  weave_weights(v_visibility, q, weight);
#else
  vec3 fabric;
  vec4 q[Q_GROUPS], weight[Q_GROUPS];
  weave_terms(n, u, wo, v_visibility, fabric, q);
  weave_weights(v_visibility, q, weight);
#endif
  o_factor = vec4(mix(weave_ratio_filtered(n, u, wo, st, dx, dy, fabric, weight), vec3(1.0), coarse), 1.0);
#endif
}
