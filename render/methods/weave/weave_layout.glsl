// The resolved weave's layout (core/weave_layout.h) and the threads' tangent curves
// (core/tangent_curve.h) in GLSL: which thread lies at tile point st, where along its float, and
// its tilt there. C++ twin: WeaveLayout::at and TangentCurve::tilt_at; tests/gpu/weave_parity_test.cpp.
#define MAX_CURVE_POINTS 16
uniform int u_weave_rows;
uniform int u_weave_shift;
uniform float u_weave_warp_share;  // f
uniform float u_weave_width;       // w
uniform int u_curve_points[2];
uniform float u_curve_tilts[2 * MAX_CURVE_POINTS];  // radians, thread j's at j·MAX_CURVE_POINTS
uniform float u_curve_arcs[2 * MAX_CURVE_POINTS];   // arc fraction of each point, 0 … 1

struct WeaveSample {
  int thread;  // 0 warp, 1 weft, −1 gap
  float arc;   // along the float, [0, 1)
};

WeaveSample weave_at(highp vec2 st) {
  highp vec2 f = fract(st);
  float rows = float(u_weave_rows);
  float tr = f.y * rows;
  float row = min(floor(tr), rows - 1.0);
  float tau = tr - row;
  float x = fract(f.x - row * float(u_weave_shift) / rows);
  if (x < u_weave_warp_share) {
    if (abs(tau - 0.5) >= 0.5 * u_weave_width) return WeaveSample(-1, 0.0);
    return WeaveSample(0, x / u_weave_warp_share);
  }
  float across = (x - u_weave_warp_share) / (1.0 - u_weave_warp_share) - 0.5;
  if (abs(across) >= 0.5 * u_weave_width) return WeaveSample(-1, 0.0);
  return WeaveSample(1, tau);
}

float curve_tilt(int j, float arc) {
  int base = j * MAX_CURVE_POINTS, points = u_curve_points[j];
  if (points == 1) return u_curve_tilts[base];
  arc = clamp(arc, 0.0, 1.0);
  int last = 0;
  for (int i = 0; i + 1 < points; ++i) {
    float a0 = u_curve_arcs[base + i], a1 = u_curve_arcs[base + i + 1];
    if (a1 <= a0) continue;  // a jump: no arc length lives here
    last = i;
    if (arc <= a1) return mix(u_curve_tilts[base + i], u_curve_tilts[base + i + 1], (arc - a0) / (a1 - a0));
  }
  return u_curve_tilts[base + last + 1];
}

// --- core/weave_coverage.h: the layout box-filtered over a pixel's footprint st ± ½dx ± ½dy (each
// axis's weight a box of |dx|'s component convolved with one of |dy|'s), per thread its share of
// the pixel, and the largest floats in it, each with its share and arc.
#define WEAVE_COVERAGE_REACH 2
#define WEAVE_COVERAGE_PIECES 4
struct WeaveCoverage {
  float share[2];
  int piece_thread[WEAVE_COVERAGE_PIECES];  // −1: an unused slot
  float piece_share[WEAVE_COVERAGE_PIECES];
  float piece_arc[WEAVE_COVERAGE_PIECES];
  // The overlap's ends along the float and the footprint's centre in the float's arc.
  float piece_arc_lo[WEAVE_COVERAGE_PIECES];
  float piece_arc_hi[WEAVE_COVERAGE_PIECES];
  float piece_centre[WEAVE_COVERAGE_PIECES];
  float arc_spread[2];  // RMS arc over the footprint along each thread's float
  vec2 arc_box[2];      // the footprint's two box widths along each thread's float, in arc
};

// ∫_{-∞}^{y} of the CDF of a box of width a centred at 0.
float box_cdf_integral(float y, float a) {
  if (a < 1e-12) return max(y, 0.0);
  float z = y / a + 0.5;
  if (z <= 0.0) return 0.0;
  return a * (z < 1.0 ? 0.5 * z * z : z - 0.5);
}
float box_pair_cdf(float x, float a, float b) {
  float wide = max(a, b), narrow = min(a, b);
  if (narrow < 1e-12) return wide < 1e-12 ? (x >= 0.0 ? 1.0 : 0.0) : clamp(x / wide + 0.5, 0.0, 1.0);
  return (box_cdf_integral(x + 0.5 * narrow, wide) - box_cdf_integral(x - 0.5 * narrow, wide)) / narrow;
}
float box_pair_mass(float lo, float hi, float a, float b) {
  return hi <= lo ? 0.0 : max(box_pair_cdf(hi, a, b) - box_pair_cdf(lo, a, b), 0.0);
}
float box_pair_density(float x, float a, float b) {
  float wide = max(a, b), narrow = min(a, b);
  if (wide < 1e-12) return 0.0;
  if (narrow < 1e-12) return abs(x) < 0.5 * wide ? 1.0 / wide : 0.0;
  return (clamp((x + 0.5 * narrow) / wide + 0.5, 0.0, 1.0) - clamp((x - 0.5 * narrow) / wide + 0.5, 0.0, 1.0)) / narrow;
}

// Adds thread j's float of share `share`, its overlap's arcs (lo, middle, hi) and the footprint
// centre's arc (weave_coverage.cpp's piece).
void add_piece(inout WeaveCoverage c, int j, float share, vec3 arcs, float centre) {
  c.share[j] += share;
  int i = WEAVE_COVERAGE_PIECES;
  while (i > 0 && share > c.piece_share[i - 1]) --i;
  if (i == WEAVE_COVERAGE_PIECES) return;
  for (int k = WEAVE_COVERAGE_PIECES - 1; k > i; --k) {
    c.piece_thread[k] = c.piece_thread[k - 1];
    c.piece_share[k] = c.piece_share[k - 1];
    c.piece_arc[k] = c.piece_arc[k - 1];
    c.piece_arc_lo[k] = c.piece_arc_lo[k - 1];
    c.piece_arc_hi[k] = c.piece_arc_hi[k - 1];
    c.piece_centre[k] = c.piece_centre[k - 1];
  }
  c.piece_thread[i] = j;
  c.piece_share[i] = share;
  c.piece_arc_lo[i] = clamp(arcs.x, 0.0, 1.0);
  c.piece_arc[i] = clamp(arcs.y, 0.0, 1.0);
  c.piece_arc_hi[i] = clamp(arcs.z, 0.0, 1.0);
  c.piece_centre[i] = centre;
}

// arc_density: the footprint's density along piece i's float at arc x.
float arc_density(WeaveCoverage c, int i, float x) {
  int j = c.piece_thread[i];
  if (j < 0) return 0.0;
  return box_pair_density(x - c.piece_centre[i], c.arc_box[j].x, c.arc_box[j].y);
}

// piece_weight: piece i's thread's share × its part of that thread's kept pieces.
float piece_weight(WeaveCoverage c, int i) {
  int j = c.piece_thread[i];
  if (j < 0) return 0.0;
  float kept = 0.0;
  for (int k = 0; k < WEAVE_COVERAGE_PIECES; ++k)
    if (c.piece_thread[k] == j) kept += c.piece_share[k];
  return c.share[j] * c.piece_share[i] / kept;
}

// The footprint's rows and floats (core/weave_coverage.h's for_each_weave_float), for
// weave_coverage and weave_ratio_tabled: the footprint centred at c (the tile's own coordinates),
// its box widths a and b (|dx|, |dy|). Rows k0 … k1 of it:
ivec2 weave_row_span(highp vec2 c, vec2 a, vec2 b) {
  float rows = float(u_weave_rows), half_y = 0.5 * (a.y + b.y);
  int kc = int(floor(c.y * rows));
  return ivec2(max(int(floor((c.y - half_y) * rows)), kc - WEAVE_COVERAGE_REACH),
               min(int(floor((c.y + half_y) * rows)), kc + WEAVE_COVERAGE_REACH));
}
// Row k: its shift o, its band [t0, t1), the masses ty of the band and wy of the warp's yarn in
// it, and the floats m0 … m1 to visit.
struct WeaveRow {
  float o, t0, t1, ty, wy;
  int m0, m1;
};
WeaveRow weave_row(int k, highp vec2 c, vec2 a, vec2 b) {
  float rows = float(u_weave_rows), w = u_weave_width, half_x = 0.5 * (a.x + b.x);
  int row = k - u_weave_rows * int(floor(float(k) / rows));  // k mod rows; GLSL's % is undefined below 0
  WeaveRow r;
  r.o = float(row * u_weave_shift) / rows;
  r.t0 = float(k) / rows;
  r.t1 = float(k + 1) / rows;
  r.ty = box_pair_mass(r.t0 - c.y, r.t1 - c.y, a.y, b.y);
  r.wy = box_pair_mass(r.t0 + (0.5 - 0.5 * w) / rows - c.y, r.t0 + (0.5 + 0.5 * w) / rows - c.y, a.y, b.y);
  int mc = int(floor(c.x - r.o));
  r.m0 = max(int(floor(c.x - half_x - r.o)) - 1, mc - WEAVE_COVERAGE_REACH);
  r.m1 = min(int(floor(c.x + half_x - r.o)), mc + WEAVE_COVERAGE_REACH);
  return r;
}
// One float's part of the footprint: its share (0: none), its overlap's arcs (lo, middle, hi) and
// the footprint centre's arc.
struct WeaveFloat {
  float share;
  vec3 arcs;
  float centre;
};
// The warp's float m of row r: over [s, s + f) in the middle w of the row.
WeaveFloat weave_warp_float(WeaveRow r, int m, highp vec2 c, vec2 a, vec2 b) {
  float f = u_weave_warp_share, half_x = 0.5 * (a.x + b.x), s = r.o + float(m);
  WeaveFloat fl = WeaveFloat(box_pair_mass(s - c.x, s + f - c.x, a.x, b.x) * r.wy, vec3(0.0), 0.0);
  if (fl.share > 0.0 && f > 0.0) {
    float lo = max(s, c.x - half_x), hi = min(s + f, c.x + half_x);
    fl.arcs = (vec3(lo, 0.5 * (lo + hi), hi) - s) / f;
    fl.centre = (c.x - s) / f;
  }
  return fl;
}
// The weft's float after warp float m of row r: across the whole row in the middle w of the rest.
WeaveFloat weave_weft_float(WeaveRow r, int m, highp vec2 c, vec2 a, vec2 b) {
  float f = u_weave_warp_share, w = u_weave_width, rows = float(u_weave_rows), half_y = 0.5 * (a.y + b.y);
  float s = r.o + float(m), g0 = s + f + (1.0 - f) * (0.5 - 0.5 * w), g1 = s + f + (1.0 - f) * (0.5 + 0.5 * w);
  WeaveFloat fl = WeaveFloat(box_pair_mass(g0 - c.x, g1 - c.x, a.x, b.x) * r.ty, vec3(0.0), 0.0);
  if (fl.share > 0.0) {
    float lo = max(r.t0, c.y - half_y), hi = min(r.t1, c.y + half_y);
    fl.arcs = (vec3(lo, 0.5 * (lo + hi), hi) - r.t0) * rows;
    fl.centre = (c.y - r.t0) * rows;
  }
  return fl;
}
// The footprint's box widths along thread j's float, in arc (WeaveCoverage::arc_box).
vec2 weave_arc_box(int j, vec2 a, vec2 b) {
  float f = u_weave_warp_share;
  if (j == 0) return f > 0.0 ? vec2(a.x, b.x) / f : vec2(0.0);
  return vec2(a.y, b.y) * float(u_weave_rows);
}

// A coverage of nothing: no share, every piece unused.
WeaveCoverage weave_coverage_empty() {
  WeaveCoverage c;
  c.share = float[2](0.0, 0.0);
  c.arc_spread = float[2](0.0, 0.0);
  for (int i = 0; i < WEAVE_COVERAGE_PIECES; ++i) {
    c.piece_thread[i] = -1;
    c.piece_share[i] = 0.0;
    c.piece_arc[i] = 0.0;
    c.piece_arc_lo[i] = 0.0;
    c.piece_arc_hi[i] = 0.0;
    c.piece_centre[i] = 0.0;
  }
  c.arc_box[0] = vec2(0.0);
  c.arc_box[1] = vec2(0.0);
  return c;
}

WeaveCoverage weave_coverage(highp vec2 st, highp vec2 dx, highp vec2 dy) {
  WeaveCoverage out_ = weave_coverage_empty();
  float f = u_weave_warp_share, rows = float(u_weave_rows);
  if (u_weave_width <= 0.0) return out_;
  highp vec2 c = fract(st);
  vec2 a = abs(dx), b = abs(dy);
  out_.arc_spread[0] = f > 0.0 ? sqrt((a.x * a.x + b.x * b.x) / 12.0) / f : 0.0;
  out_.arc_spread[1] = sqrt((a.y * a.y + b.y * b.y) / 12.0) * rows;
  out_.arc_box[0] = weave_arc_box(0, a, b);
  out_.arc_box[1] = weave_arc_box(1, a, b);
  ivec2 ks = weave_row_span(c, a, b);
  for (int k = ks.x; k <= ks.y; ++k) {
    WeaveRow r = weave_row(k, c, a, b);
    for (int m = r.m0; m <= r.m1; ++m) {
      WeaveFloat fl = weave_warp_float(r, m, c, a, b);
      if (fl.share > 0.0) add_piece(out_, 0, fl.share, fl.arcs, fl.centre);
      fl = weave_weft_float(r, m, c, a, b);
      if (fl.share > 0.0) add_piece(out_, 1, fl.share, fl.arcs, fl.centre);
    }
  }
  return out_;
}
