// The per-vertex pass's layout (methods/vertex_pass/vertex_pass.h), for the passes' fragment shaders:
// one fragment per (pass vertex n, block k) at texel (n mod W, n div W + k·rows), each pass
// vertex's position, normal and warp at its texel of block 0, the mesh vertex it is in the
// position's .w. Every mesh vertex is a pass vertex (n = i) unless the mesh is denser than its
// shading needs (scene/vertex_pass_mesh.h): then the pass vertices are a subset, and what is kept
// per mesh vertex (baked visibility, masks, marks, the weave's reach) is read at the mesh vertex i.
uniform highp sampler2D u_vertex_position;
uniform highp sampler2D u_vertex_normal;
uniform highp sampler2D u_vertex_warp;
uniform int u_vertex_width;
uniform int u_vertex_rows;
uniform int u_vertex_count;       // pass vertices
uniform int u_vertex_mesh_width;  // texels a row of what is kept per mesh vertex
uniform int u_vertex_mesh_rows;   // its rows a block (the results the draw reads: VertexPass::bind_result)
uniform float u_pass_time;  // the run's time (VertexPass::set_history): iwasaki's passes write it in .w

struct PassTexel {
  ivec2 p;    // the pass vertex's texel in block 0
  int k;      // the block (an SG, where the pass writes one per block)
  int i;      // the mesh vertex
  ivec2 m;    // the mesh vertex's texel in a per-mesh-vertex layout
  bool past;  // a texel past the last pass vertex: writes 0
};
PassTexel pass_texel() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int k = p.y / u_vertex_rows;
  p.y -= k * u_vertex_rows;
  int n = p.y * u_vertex_width + p.x;
  bool past = n >= u_vertex_count;
  int i = past ? 0 : int(texelFetch(u_vertex_position, p, 0).w + 0.5);
  return PassTexel(p, k, i, ivec2(i % u_vertex_mesh_width, i / u_vertex_mesh_width), past);
}

// Visible vertices only (vertex_pass.h's set_marks): whether the texel keeps its value this run.
// A vertex is recomputed when a visible triangle uses it (its mark is this run's stamp) and it
// is in its block's share of this run, or it was not visible at the run before (its kept value
// may be from any time).
#define MAX_PASS_BLOCKS 40
uniform bool u_vertex_cull;
uniform highp usampler2D u_vertex_mark;
uniform highp usampler2D u_vertex_mark_before;
uniform uint u_vertex_stamp;
uniform uint u_vertex_stamp_before;
uniform ivec2 u_vertex_range[MAX_PASS_BLOCKS];  // block k recomputes vertices [x, y)
// pass_keeps_turn also takes the eye, for a pass that shades the side of a vertex facing it: a
// visible vertex seen within ~3° of its tangent plane is then recomputed at every run, its turn or
// not, since a kept value there may be of its other side (the side shaded flips with the eye); a
// turntable takes several frames to turn a vertex 3°. pass_keeps: no such vertex.
bool pass_keeps_turn(PassTexel t, vec3 eye) {
  if (!u_vertex_cull) return false;  // always so where the pass vertices are a subset
  if (texelFetch(u_vertex_mark, t.m, 0).r != u_vertex_stamp) return true;
  if (eye != vec3(0.0)) {
    vec3 n = texelFetch(u_vertex_normal, t.p, 0).xyz, p = texelFetch(u_vertex_position, t.p, 0).xyz;
    if (abs(dot(normalize(n), normalize(eye - p))) < 0.05) return false;
  }
  ivec2 r = u_vertex_range[t.k];
  if (t.i >= r.x && t.i < r.y) return false;
  return texelFetch(u_vertex_mark_before, t.m, 0).r == u_vertex_stamp_before;
}
bool pass_keeps(PassTexel t) { return pass_keeps_turn(t, vec3(0.0)); }

