// Method `sheer_vertex`, step 1 (methods/vertex_pass/vertex_pass.h): the sheer layer (sheer.glsl) at
// every mesh vertex, one fragment per vertex i at texel (i mod W, i div W), with the vertex's own
// SDF values: premultiplied source and alpha. sheer_vertex.vert reads them by gl_VertexID.
out vec4 o_radiance;
void main() {
  PassTexel t = pass_texel();  // one block
  ivec2 p = t.p;
  int i = t.i;
  if (t.past) {
    o_radiance = vec4(0.0);
    return;
  }
  sheer_position = texelFetch(u_vertex_position, p, 0).xyz;
  sheer_mesh_normal = texelFetch(u_vertex_normal, p, 0).xyz;
  sheer_warp = texelFetch(u_vertex_warp, p, 0).xyz;
  sheer_corners = ivec3(i);
  sheer_bary = vec3(1.0, 0.0, 0.0);
  vec3 n = normalize(sheer_mesh_normal);
  o_radiance = thin_radiance(n, normalize(sheer_warp - dot(sheer_warp, n) * n), normalize(u_eye - sheer_position));
}
