// The weave layer's per-float table (methods/weave/weave_float_table.h): each thread's resolved
// response at WEAVE_TABLE_ARCS cell centres along its float, made per vertex by
// weave_table_pass.frag and read per pixel, interpolated from the vertices, by weave_ratio_tabled.
// Needs microcylinder.glsl, erf.glsl, weave_layout.glsl and weave_ratio.glsl before it, and
// WEAVE_TABLE_ARCS and WEAVE_TABLE_NODES (weave_defines: kWeaveTableArcs).

float weave_table_arc(int m) { return (float(m) + 0.5) / float(WEAVE_TABLE_ARCS); }

// Node m of thread j as a pixel's coverage: the cell its one piece, seen uniformly (weave_table_cell).
WeaveCoverage weave_table_cell(int j, int m) {
  float width = 1.0 / float(WEAVE_TABLE_ARCS), centre = weave_table_arc(m);
  WeaveCoverage c = weave_coverage_empty();
  c.share[j] = 1.0;
  c.piece_thread[0] = j;
  c.piece_share[0] = 1.0;
  c.piece_arc[0] = centre;
  c.piece_arc_lo[0] = float(m) * width;
  c.piece_arc_hi[0] = float(m + 1) * width;
  c.piece_centre[0] = centre;
  c.arc_box[j] = vec2(width, 0.0);
  c.arc_spread[j] = width / sqrt(12.0);
  return c;
}

// Node m of thread j at a point: weave_float_table's entry j·WEAVE_TABLE_ARCS + m.
vec3 weave_table_node(vec3 n, vec3 u, vec3 wo, int j, int m, vec4 weight[Q_GROUPS]) {
  HorizonLight lights[MAX_SGS];
  horizon_lights(n, lights);
  return weave_float_response(n, u, wo, weave_table_cell(j, m), 0, weight, lights);
}

vec3 weave_table_at(vec3 table[WEAVE_TABLE_NODES], int j, float arc) {
  float x = clamp(arc * float(WEAVE_TABLE_ARCS) - 0.5, 0.0, float(WEAVE_TABLE_ARCS - 1));
  int m = min(int(x), WEAVE_TABLE_ARCS - 2);
  int base = j * WEAVE_TABLE_ARCS + m;
  return mix(table[base], table[base + 1], x - float(m));
}

// Adds to each node's weight w[n] float fl's share of it: the float averaged over its arc range
// at three Gauss–Legendre points weighted by the footprint's density there (box: weave_arc_box),
// each point spread over its two nodes as weave_table_at interpolates. The nodes by a loop of
// constant bounds and each point's hat: no array is indexed by a computed index, which a CPU
// rasteriser pays for per lane.
void weave_table_weights(inout float w[WEAVE_TABLE_ARCS], WeaveFloat fl, vec2 box) {
  vec3 arcs = clamp(fl.arcs, 0.0, 1.0);
  float mid = 0.5 * (arcs.x + arcs.z), half_ = 0.5 * (arcs.z - arcs.x);
  vec3 at = vec3(arcs.y), weight = vec3(0.0, 1.0, 0.0);
  if (half_ > 0.0) {
    at = mid + vec3(-1.0, 0.0, 1.0) * 0.7745966692414834 * half_;
    vec3 density = vec3(box_pair_density(at.x - fl.centre, box.x, box.y), box_pair_density(at.y - fl.centre, box.x, box.y),
                        box_pair_density(at.z - fl.centre, box.x, box.y));
    vec3 g = vec3(5.0, 8.0, 5.0) / 18.0 * half_ * density;
    float total = g.x + g.y + g.z;
    if (total > 0.0) weight = g / total; else at = vec3(arcs.y);
  }
  vec3 x = clamp(at * float(WEAVE_TABLE_ARCS) - 0.5, 0.0, float(WEAVE_TABLE_ARCS - 1));
  weight *= fl.share;
  // Three points between the same two nodes (a pixel's part of a float within a cell, the
  // close-up's usual case): the hats are linear there, so their weighted mean point alone gives
  // the same weights at a third of the work.
  int first = min(int(min(x.x, min(x.y, x.z))), WEAVE_TABLE_ARCS - 2), last = min(int(max(x.x, max(x.y, x.z))), WEAVE_TABLE_ARCS - 2);
  float total = weight.x + weight.y + weight.z;
  if (first == last && total > 0.0) {
    float mean = dot(weight, x) / total;
    for (int n = 0; n < WEAVE_TABLE_ARCS; ++n) w[n] += total * max(1.0 - abs(mean - float(n)), 0.0);
    return;
  }
  for (int n = 0; n < WEAVE_TABLE_ARCS; ++n) w[n] += dot(weight, max(1.0 - abs(x - float(n)), 0.0));
}

// The factor over the pixel's footprint from the table: the layout box-filtered over it, every
// float in it (weave_table_weights), over `fabric`.
// Twin: weave_ratio_tabled in methods/weave/weave_float_table.h.
vec3 weave_ratio_tabled(highp vec2 st, highp vec2 dx, highp vec2 dy, vec3 fabric, vec3 table[WEAVE_TABLE_NODES]) {
  float warp[WEAVE_TABLE_ARCS], weft[WEAVE_TABLE_ARCS];
  for (int n = 0; n < WEAVE_TABLE_ARCS; ++n) warp[n] = weft[n] = 0.0;
  if (u_weave_width > 0.0) {
    highp vec2 c = fract(st);
    vec2 a = abs(dx), b = abs(dy);
    vec2 warp_box = weave_arc_box(0, a, b), weft_box = weave_arc_box(1, a, b);
    ivec2 ks = weave_row_span(c, a, b);
    for (int k = ks.x; k <= ks.y; ++k) {
      WeaveRow r = weave_row(k, c, a, b);
      for (int m = r.m0; m <= r.m1; ++m) {
        WeaveFloat fl = weave_warp_float(r, m, c, a, b);
        if (fl.share > 0.0) weave_table_weights(warp, fl, warp_box);
        fl = weave_weft_float(r, m, c, a, b);
        if (fl.share > 0.0) weave_table_weights(weft, fl, weft_box);
      }
    }
  }
  vec3 resolved = vec3(0.0);
  for (int n = 0; n < WEAVE_TABLE_ARCS; ++n) resolved += warp[n] * table[n] + weft[n] * table[WEAVE_TABLE_ARCS + n];
  return ratio_to(resolved, fabric);
}
