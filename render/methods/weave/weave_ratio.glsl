// The weave layer's factor (methods/weave/weave_ratio.h): the resolved sample's response to the SGs
// taken as point lights (each lobe widened by the SG's own spread), over the fabric-level response to the same lights, so that the factor
// averages to 1 over the repeat and modulates what the fabric-level method drew. Needs
// microcylinder.glsl and weave_layout.glsl before it, and MAX_SGS.
uniform int u_sg_count;
uniform vec3 u_sg_axis[MAX_SGS];
uniform vec3 u_sg_power[MAX_SGS];
uniform float u_sg_widen2[MAX_SGS];  // weave_lobe_widening(λ_k)

// What thread j's sample at tilt α needs of ω_o alone, taken once for all the SGs: its frame
// (t, n', axis) and ω_o's fiber angles in it; `lit` false where ω_o is below the surface.
struct ResolvedView {
  vec3 t, np, axis;
  FiberAngles fo;
  bool lit;
};
ResolvedView resolved_view(vec3 n, vec3 u, int j, float alpha, vec3 wo) {
  vec3 v = cross(n, u);
  vec3 along = j == 0 ? u : v, axis = j == 0 ? v : u;
  SampleFrame f = sample_frame(along, n, alpha);
  return ResolvedView(f.t, f.np, axis, fiber_angles_in(f.t, f.np, axis, wo), dot(n, wo) > 0.0);
}

// f_s · M · P · cos θ_i of thread j's sample seen as `view`: ClothBsdf::Point::resolved_scattering.
vec3 resolved_scattering(ResolvedView view, vec3 n, int j, vec3 wi, float widen2) {
  if (dot(n, wi) <= 0.0 || !view.lit) return vec3(0.0);
  FiberAngles fi = fiber_angles_in(view.t, view.np, view.axis, wi);
  float p = projection_term(fi, view.fo);
  if (p <= 0.0) return vec3(0.0);
  float w = masking_term(fi, view.fo) * p;
  if (w <= 0.0) return vec3(0.0);
  return scattering(widened(u_threads[j], widen2), fi, view.fo) * (w * cos(fi.theta));
}

// Σ_k P_k f_s M P cos θ_i / Q_k of thread j's sample at arc position `arc` of its float.
vec3 resolved_response(vec3 n, vec3 u, vec3 wo, int j, float arc, vec4 q[Q_GROUPS]) {
  ResolvedView view = resolved_view(n, u, j, curve_tilt(j, arc), wo);
  vec3 resolved = vec3(0.0);
  if (!view.lit) return resolved;
  for (int g = 0; g < Q_GROUPS; ++g)
    for (int c = 0; c < 4; ++c) {
      int k = 4 * g + c;
      if (k >= u_sg_count) break;
      if (q[g][c] <= Q_FLOOR) continue;
      resolved += u_sg_power[k] * resolved_scattering(view, n, j, u_sg_axis[k], u_sg_widen2[k]) / q[g][c];
    }
  return resolved;
}

vec3 ratio_to(vec3 resolved, vec3 fabric) {
  vec3 ratio;
  for (int c = 0; c < 3; ++c) ratio[c] = fabric[c] > RATIO_FLOOR ? min(resolved[c] / fabric[c], RATIO_CAP) : 1.0;
  return ratio;
}

// The factor at tile point st, given the fabric-level response `fabric` (Σ_k P_k·integrand) and
// each SG's Q (`q`, packed four to a vec4) interpolated from the vertices.
vec3 weave_ratio(vec3 n, vec3 u, vec3 wo, highp vec2 st, vec3 fabric, vec4 q[Q_GROUPS]) {
  WeaveSample w = weave_at(st);
  if (w.thread < 0) return vec3(0.0);
  return ratio_to(resolved_response(n, u, wo, w.thread, w.arc, q), fabric);
}

// The factor averaged over the pixel's footprint (tile-space derivatives dx, dy): the layout at
// four rotated-grid points, gap samples adding nothing. A thread whose samples lie close along
// its float (a close-up) is shaded once at their mean position, weighted by its share of them;
// one whose samples spread further (near the level-of-detail ease) is shaded at each. So a yarn's
// edge covers the pixel in part, as in a supersampled reference, for one or two shading
// evaluations a pixel up close. Twin: weave_ratio_filtered in methods/weave/weave_ratio.h.
#define WEAVE_ARC_SPREAD 0.125
vec3 weave_ratio_filtered(vec3 n, vec3 u, vec3 wo, highp vec2 st, highp vec2 dx, highp vec2 dy, vec3 fabric,
                          vec4 q[Q_GROUPS]) {
  const vec2 grid[4] = vec2[4](vec2(-0.125, -0.375), vec2(0.375, -0.125), vec2(0.125, 0.375), vec2(-0.375, 0.125));
  int thread[4];
  float arc[4];
  float count[2] = float[2](0.0, 0.0), sum[2] = float[2](0.0, 0.0);
  float lo[2] = float[2](1.0, 1.0), hi[2] = float[2](0.0, 0.0);
  for (int i = 0; i < 4; ++i) {
    WeaveSample w = weave_at(st + grid[i].x * dx + grid[i].y * dy);
    thread[i] = w.thread;
    arc[i] = w.arc;
    if (w.thread < 0) continue;
    int j = w.thread;
    count[j] += 1.0;
    sum[j] += w.arc;
    lo[j] = min(lo[j], w.arc);
    hi[j] = max(hi[j], w.arc);
  }
  vec3 resolved = vec3(0.0);
  for (int j = 0; j < 2; ++j) {
    if (count[j] == 0.0) continue;
    if (hi[j] - lo[j] <= WEAVE_ARC_SPREAD) {
      resolved += 0.25 * count[j] * resolved_response(n, u, wo, j, sum[j] / count[j], q);
      continue;
    }
    for (int i = 0; i < 4; ++i)
      if (thread[i] == j) resolved += 0.25 * resolved_response(n, u, wo, j, arc[i], q);
  }
  return ratio_to(resolved, fabric);
}
