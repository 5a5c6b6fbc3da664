// The weave layer's factor (methods/weave/weave_ratio.h): the resolved sample's response to the SGs
// taken as point lights (each lobe widened by the SG's own spread; each weighted by the share V_k the
// object's geometry leaves open), over the fabric-level response to the same lights at the same pixel, so that the factor averages to 1 over the repeat and
// modulates what the fabric-level method drew. Needs microcylinder.glsl, erf.glsl and
// weave_layout.glsl before it, and MAX_SGS.
uniform int u_sg_count;
uniform vec3 u_sg_axis[MAX_SGS];
uniform vec3 u_sg_power[MAX_SGS];
uniform float u_sg_widen2[MAX_SGS];  // weave_lobe_widening(λ_k)
// ClothBsdf::tilt_spread of each tangent sample, laid out as u_tilts (microcylinder.glsl).
uniform vec4 u_weave_tilt_spreads[MAX_TANGENT_SAMPLES / 2];

// SG k as a point light seen from a surface of normal n: its part above the horizon (share F of its
// power) at that part's mean elevation (weave_ratio.h's horizon_light); σ = 1/√λ = 2·√widen2.
struct HorizonLight {
  vec3 axis;
  float share;
};
HorizonLight horizon_light(int k, vec3 n) {
  vec3 xi = u_sg_axis[k];
  float sigma = 2.0 * sqrt(u_sg_widen2[k]);
  float c = clamp(dot(xi, n), -1.0, 1.0);
  float e0 = asin(c), z = e0 / sigma;
  float share = 0.5 * erfc_nr(-z / sqrt(2.0));
  if (share <= 0.0) return HorizonLight(xi, 0.0);
  float lift = sigma * exp(-0.5 * z * z) / (sqrt(2.0 * PI) * share);
  vec3 level = xi - c * n;
  float level_length = length(level);
  if (lift < 1e-9 || level_length < 1e-9) return HorizonLight(xi, share);
  float e = min(e0 + lift, 0.5 * PI);
  return HorizonLight(cos(e) * (level / level_length) + sin(e) * n, share);
}

// Each SG's horizon_light at n, into lights[0 … u_sg_count − 1]: taken once a pixel for all its floats.
void horizon_lights(vec3 n, out HorizonLight lights[MAX_SGS]) {
  for (int k = 0; k < u_sg_count; ++k) lights[k] = horizon_light(k, n);
}

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

// f_s · M · P · cos θ_i of thread j's sample seen as `view`, both lobes widened by widen2 and by
// the sample's tilt spread as seen from ω_i and ω_o (weave_ratio.cpp's sample_terms).
vec3 resolved_scattering(ResolvedView view, vec3 n, int j, vec3 wi, float widen2, float tilt_spread) {
  if (dot(n, wi) <= 0.0 || !view.lit) return vec3(0.0);
  FiberAngles fi = fiber_angles_in(view.t, view.np, view.axis, wi);
  float p = projection_term(fi, view.fo);
  if (p <= 0.0) return vec3(0.0);
  float w = masking_term(fi, view.fo) * p;
  if (w <= 0.0) return vec3(0.0);
  float c = 0.5 * (cos(fi.phi) + cos(view.fo.phi)) * tilt_spread;
  return scattering(widened(u_threads[j], widen2 + c * c), fi, view.fo) * (w * cos(fi.theta));
}

// The pixel's fabric-level terms (weave_terms in weave_ratio.h): Σ_k V_k P_k·integrand(ξ_k, ω_o)
// over the program's tangent samples, each widened by the SG's spread and its own tilt spread, and
// each SG's Q, four to a vec4; `vis`: V_k, four to a vec4.
void weave_terms(vec3 n, vec3 u, vec3 wo, vec4 vis[Q_GROUPS], out vec3 fabric, out vec4 q[Q_GROUPS]) {
  // One sweep over the samples, each sample's view taken once for all the SGs.
  vec3 sums[MAX_SGS];
  float qs[MAX_SGS];
  HorizonLight lights[MAX_SGS];
  horizon_lights(n, lights);
  float gap_q = (1.0 - u_threads[0].coverage - u_threads[1].coverage) * max(dot(n, wo), 0.0);
  for (int k = 0; k < u_sg_count; ++k) {
    sums[k] = vec3(0.0);
    qs[k] = gap_q;
  }
  for (int j = 0; j < 2; ++j) {
    float share = u_threads[j].coverage / float(u_threads[j].samples);
    for (int s = 0; s < u_threads[j].samples; ++s) {
      int i = j * MAX_TANGENT_SAMPLES + s;
      ResolvedView view = resolved_view(n, u, j, thread_tilt(i), wo);
      float spread = u_weave_tilt_spreads[i >> 2][i & 3];
      for (int k = 0; k < u_sg_count; ++k) {
        vec3 wi = lights[k].axis;
        qs[k] += share * projection_term(fiber_angles_in(view.t, view.np, view.axis, wi), view.fo);
        sums[k] += share * resolved_scattering(view, n, j, wi, u_sg_widen2[k], spread);
      }
    }
  }
  fabric = vec3(0.0);
  for (int g = 0; g < Q_GROUPS; ++g) q[g] = vec4(0.0);
  for (int k = 0; k < u_sg_count; ++k) {
    q[k >> 2][k & 3] = qs[k];
    if (qs[k] > Q_FLOOR && lights[k].share > 0.0)
      fabric += vis[k >> 2][k & 3] * lights[k].share * u_sg_power[k] * sums[k] / qs[k];
  }
}

// weave_terms' Q of lights first … first + count − 1 alone (the projection terms, no scattering),
// into qs[0 … count − 1]; 0 past the last light.
void weave_q_lights(vec3 n, vec3 u, vec3 wo, int first, int count, out float qs[MAX_SGS]) {
  vec3 axes[MAX_SGS];
  float gap_q = (1.0 - u_threads[0].coverage - u_threads[1].coverage) * max(dot(n, wo), 0.0);
  for (int c = 0; c < count; ++c) {
    axes[c] = first + c < u_sg_count ? horizon_light(first + c, n).axis : n;
    qs[c] = gap_q;
  }
  for (int j = 0; j < 2; ++j) {
    float share = u_threads[j].coverage / float(u_threads[j].samples);
    for (int s = 0; s < u_threads[j].samples; ++s) {
      ResolvedView view = resolved_view(n, u, j, thread_tilt(j * MAX_TANGENT_SAMPLES + s), wo);
      for (int c = 0; c < count; ++c) qs[c] += share * projection_term(fiber_angles_in(view.t, view.np, view.axis, axes[c]), view.fo);
    }
  }
  for (int c = 0; c < count; ++c)
    if (first + c >= u_sg_count) qs[c] = 0.0;
}

// The Qs of lights 4g … 4g + 3, for a pass that writes one group of four at a time.
vec4 weave_q_group(vec3 n, vec3 u, vec3 wo, int g) {
  float qs[MAX_SGS];
  weave_q_lights(n, u, wo, 4 * g, 4, qs);
  return vec4(qs[0], qs[1], qs[2], qs[3]);
}

// Every light's Q, four to a vec4, in one sweep over the samples.
void weave_qs(vec3 n, vec3 u, vec3 wo, out vec4 q[Q_GROUPS]) {
  float qs[MAX_SGS];
  weave_q_lights(n, u, wo, 0, u_sg_count, qs);
  for (int g = 0; g < Q_GROUPS; ++g) q[g] = vec4(0.0);
  for (int k = 0; k < u_sg_count; ++k) q[k >> 2][k & 3] = qs[k];
}

// Each light's weight in the resolved response, V_k/Q_k (0 where Q_k ≤ Q_FLOOR): weave_terms' Q and
// the visibility the pixel has (its own, or both interpolated from the vertices).
void weave_weights(vec4 vis[Q_GROUPS], vec4 q[Q_GROUPS], out vec4 weight[Q_GROUPS]) {
  for (int g = 0; g < Q_GROUPS; ++g)
    for (int c = 0; c < 4; ++c) weight[g][c] = q[g][c] > Q_FLOOR ? vis[g][c] / q[g][c] : 0.0;
}

// Σ_k P_k f_s M P cos θ_i · V_k/Q_k of thread j's sample at arc position `arc` of its float, its
// lobes widened by `tilt_spread` (RMS, radians) besides each SG's own spread; SG k is the point
// light lights[k] (horizon_lights at n); `weight`: weave_weights' V_k/Q_k.
vec3 resolved_response(vec3 n, vec3 u, vec3 wo, int j, float arc, float tilt_spread, vec4 weight[Q_GROUPS],
                       HorizonLight lights[MAX_SGS]) {
  ResolvedView view = resolved_view(n, u, j, curve_tilt(j, arc), wo);
  vec3 resolved = vec3(0.0);
  if (!view.lit) return resolved;
  for (int g = 0; g < Q_GROUPS; ++g)
    for (int c = 0; c < 4; ++c) {
      int k = 4 * g + c;
      if (k >= u_sg_count) break;
      if (weight[g][c] <= 0.0) continue;
      if (lights[k].share <= 0.0) continue;
      resolved += lights[k].share * u_sg_power[k] * weight[g][c] * resolved_scattering(view, n, j, lights[k].axis, u_sg_widen2[k], tilt_spread);
    }
  return resolved;
}

vec3 ratio_to(vec3 resolved, vec3 fabric) {
  vec3 ratio;
  for (int c = 0; c < 3; ++c) ratio[c] = fabric[c] > RATIO_FLOOR ? min(resolved[c] / fabric[c], RATIO_CAP) : 1.0;
  return ratio;
}

// The factor at tile point st, given weave_terms' fabric-level response `fabric` and the lights'
// weights (weave_weights, packed four to a vec4).
vec3 weave_ratio(vec3 n, vec3 u, vec3 wo, highp vec2 st, vec3 fabric, vec4 weight[Q_GROUPS]) {
  WeaveSample w = weave_at(st);
  if (w.thread < 0) return vec3(0.0);
  HorizonLight lights[MAX_SGS];
  horizon_lights(n, lights);
  return ratio_to(resolved_response(n, u, wo, w.thread, w.arc, 0.0, weight, lights), fabric);
}

// The RMS tilt of thread j's float over an arc spread `arc_spread` (RMS) about `arc`: the
// curve's slope there times the spread, the slope the gentler of the two sides' within √3 spreads
// (a jump of the curve on one side is two tilts, not a spread): weave_tilt_spread.
float weave_tilt_spread(int j, float arc, float arc_spread) {
  if (arc_spread <= 0.0) return 0.0;
  float h = sqrt(3.0) * arc_spread, here = curve_tilt(j, arc);
  float slope = 1e30;
  if (arc < 1.0) {
    float b = min(arc + h, 1.0);
    slope = abs(curve_tilt(j, b) - here) / (b - arc);
  }
  if (arc > 0.0) {
    float a = max(arc - h, 0.0);
    slope = min(slope, abs(here - curve_tilt(j, a)) / (arc - a));
  }
  return slope < 1e30 ? slope * arc_spread : 0.0;
}

// weave_float_response's three Gauss–Legendre arcs over one stretch [lo, hi] of piece i's range,
// each weighted by the footprint's density there (times the stretch's half-length) and widened by
// the tilts of its part of the stretch; adds to sum and total.
void weave_stretch(vec3 n, vec3 u, vec3 wo, WeaveCoverage c, int i, float lo, float hi, vec4 weight[Q_GROUPS],
                   HorizonLight lights[MAX_SGS], inout vec3 sum, inout float total) {
  int j = c.piece_thread[i];
  float mid = 0.5 * (lo + hi), half_ = 0.5 * (hi - lo);
  for (int m = 0; m < 3; ++m) {
    float a = mid + float(m - 1) * 0.7745966692414834 * half_;
    float gl = m == 1 ? 8.0 / 18.0 : 5.0 / 18.0;
    float w = gl * half_ * arc_density(c, i, a);
    if (w <= 0.0) continue;
    sum += w * resolved_response(n, u, wo, j, a, weave_tilt_spread(j, a, gl * 2.0 * half_ / sqrt(12.0)), weight, lights);
    total += w;
  }
}

// weave_float_response: piece i of coverage c averaged over its arc range, stretch by stretch
// between the curve's jumps (a zero-length segment), at three Gauss–Legendre arcs each (at its
// middle arc, widened by the footprint's tilts, where the range is a point).
vec3 weave_float_response(vec3 n, vec3 u, vec3 wo, WeaveCoverage c, int i, vec4 weight[Q_GROUPS],
                          HorizonLight lights[MAX_SGS]) {
  int j = c.piece_thread[i];
  float lo = c.piece_arc_lo[i], hi = c.piece_arc_hi[i];
  if (hi > lo) {
    vec3 sum = vec3(0.0);
    float total = 0.0, from = lo;
    int base = j * MAX_CURVE_POINTS;
    for (int k = 0; k + 1 < u_curve_points[j]; ++k) {
      float jump = u_curve_arcs[base + k];
      if (u_curve_arcs[base + k + 1] > jump || jump <= from || jump >= hi) continue;
      weave_stretch(n, u, wo, c, i, from, jump, weight, lights, sum, total);
      from = jump;
    }
    weave_stretch(n, u, wo, c, i, from, hi, weight, lights, sum, total);
    if (total > 0.0) return sum / total;
  }
  float arc = c.piece_arc[i];
  return resolved_response(n, u, wo, j, arc, weave_tilt_spread(j, arc, c.arc_spread[j]), weight, lights);
}

// The factor over the pixel's footprint (tile-space derivatives dx, dy): the layout box-filtered
// over it (weave_coverage), each of its largest floats shaded where it lies
// (weave_float_response), weighted by its share of the pixel.
// Twin: weave_ratio_filtered in methods/weave/weave_ratio.h.
vec3 weave_ratio_filtered(vec3 n, vec3 u, vec3 wo, highp vec2 st, highp vec2 dx, highp vec2 dy, vec3 fabric,
                          vec4 weight[Q_GROUPS]) {
  WeaveCoverage c = weave_coverage(st, dx, dy);
  HorizonLight lights[MAX_SGS];
  horizon_lights(n, lights);
  vec3 resolved = vec3(0.0);
  for (int i = 0; i < WEAVE_COVERAGE_PIECES; ++i) {
    if (c.piece_thread[i] < 0) break;
    resolved += piece_weight(c, i) * weave_float_response(n, u, wo, c, i, weight, lights);
  }
  return ratio_to(resolved, fabric);
}
