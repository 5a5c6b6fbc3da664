// Where the pass vertices are a subset of the mesh's (scene/vertex_pass_mesh.h): every mesh
// vertex's value in each block, blended from its three pass vertices' values by its weights,
// into the layout the draws read by gl_VertexID (texel (i mod W, i div W + k·rows)). Linear in the
// values, as the rasteriser's blend of a triangle's corners is.
uniform highp sampler2D u_pass_values;  // the pass's target: pass vertex n of block k at (n mod W', n div W' + k·rows')
uniform highp sampler2D u_blend_corners;  // per mesh vertex: its three pass vertices (.xyz, exact integers)
uniform highp sampler2D u_blend_weights;  // per mesh vertex: their weights (.xyz)
uniform int u_pass_width;
uniform int u_pass_rows;
uniform int u_mesh_width;
uniform int u_mesh_rows;
uniform int u_mesh_count;
uniform bool u_blend_cull;               // only the marked mesh vertices (VertexPass::set_marks)
uniform highp usampler2D u_blend_marks;  // per mesh vertex: the stamp of the view that shows it
uniform uint u_blend_stamp;
out vec4 o_value;
vec4 pass_value(int n, int k) { return texelFetch(u_pass_values, ivec2(n % u_pass_width, n / u_pass_width + k * u_pass_rows), 0); }
void main() {
  ivec2 q = ivec2(gl_FragCoord.xy);
  int k = q.y / u_mesh_rows;
  q.y -= k * u_mesh_rows;
  if (q.y * u_mesh_width + q.x >= u_mesh_count) {
    o_value = vec4(0.0);
    return;
  }
  if (u_blend_cull && texelFetch(u_blend_marks, q, 0).r != u_blend_stamp) discard;  // keeps its last blend
  ivec3 c = ivec3(texelFetch(u_blend_corners, q, 0).xyz + 0.5);
  vec3 w = texelFetch(u_blend_weights, q, 0).xyz;
  o_value = w.x * pass_value(c.x, k) + w.y * pass_value(c.y, k) + w.z * pass_value(c.z, k);
}
