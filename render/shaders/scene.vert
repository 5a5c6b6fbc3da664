// Every scene surface: world-space position, normal and warp to the fragment stage, plus the
// per-vertex colour slot (SG irradiance for Lambertian surfaces, refilled on light changes), and
// a cloth's UVs (location 6, as (u, v, 0); (0, 0) on meshes without) for its textures.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_warp;
layout(location = 3) in vec3 a_colour;
layout(location = 6) in vec3 a_uv;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_warp;
out vec3 v_colour;
out vec2 v_uv;
void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_warp = a_warp;
  v_colour = a_colour;
  v_uv = a_uv.xy;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
