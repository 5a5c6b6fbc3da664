// A per-vertex pass's value extrapolated to the frame's time (methods/vertex_pass/vertex_pass.h's
// set_history): with temporal reuse a vertex is recomputed once per round of its block's shares,
// and while the camera turns a kept value lags the view. The pass keeps, per texel, its latest
// value a (time in a.w) and the one before b; the line through them carried on to now follows
// the view to second order instead of holding the first. Only a chord of the texel's own latest
// turns counts: both after the last whole pass (u_history_floor: no chord across a knob, a light
// or a jump) and no longer than the block's round allows (u_history_gap[block], 0: none), nor
// carried further than that; no part of a split goes below 0.
uniform highp sampler2D u_vertex_history;
uniform float u_history_now;
uniform float u_history_floor;
uniform float u_history_gap[MAX_PASS_VALUES];
vec3 extrapolated_value(vec4 a, ivec2 texel, int block) {
  vec4 b = texelFetch(u_vertex_history, texel, 0);
  float chord = a.w - b.w, step = u_history_now - a.w, gap = u_history_gap[block];
  if (!(b.w >= u_history_floor && chord > 0.0 && chord <= gap && step <= gap)) return a.rgb;
  return max(a.rgb + (step / chord) * (a.rgb - b.rgb), vec3(0.0));
}
