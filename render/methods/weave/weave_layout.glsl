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
