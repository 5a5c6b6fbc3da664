// The per-vertex pass's layout (methods/iwasaki/vertex_pass.h), for the passes' fragment shaders:
// one fragment per (vertex i, block k) at texel (i mod W, i div W + k·rows), each vertex's
// position, normal and warp at its texel of block 0.
uniform highp sampler2D u_vertex_position;
uniform highp sampler2D u_vertex_normal;
uniform highp sampler2D u_vertex_warp;
uniform int u_vertex_width;
uniform int u_vertex_rows;
uniform int u_vertex_count;

struct PassTexel {
  ivec2 p;  // the vertex's texel in block 0
  int k;    // the block (an SG, where the pass writes one per block)
  int i;    // the vertex; ≥ u_vertex_count: a texel past the last vertex
};
PassTexel pass_texel() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int k = p.y / u_vertex_rows;
  p.y -= k * u_vertex_rows;
  return PassTexel(p, k, p.y * u_vertex_width + p.x);
}
