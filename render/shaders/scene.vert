// Every scene surface: world-space position, normal and warp to the fragment stage, plus the
// per-vertex colour slot (SG irradiance for Lambertian surfaces, refilled on light changes).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_warp;
layout(location = 3) in vec3 a_colour;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_warp;
out vec3 v_colour;
void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_warp = a_warp;
  v_colour = a_colour;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
