// Method `iwasaki`: scene.vert's outputs plus what the per-pixel visibility needs (docs/design.md §4,
// seed 000 §3.2 "SDF is interpolated at each pixel"): the triangle's three vertex indices (the
// mesh is drawn de-indexed, every corner carrying all three) and a one-hot barycentric the
// rasteriser interpolates; and the UV a textured cloth reads its thread maps at.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_warp;
layout(location = 3) in vec3 a_colour;
layout(location = 4) in vec3 a_corners;
layout(location = 5) in vec3 a_bary;
layout(location = 6) in vec3 a_uv;  // (u, v, 0): thread_maps.glsl's textures
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_warp;
flat out vec3 v_corners;
out vec3 v_bary;
out vec2 v_uv;
void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_warp = a_warp;
  v_corners = a_corners;
  v_bary = a_bary;
  v_uv = a_uv.xy;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
