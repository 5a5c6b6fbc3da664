// Method `sheen` (docs/design.md §4): the peer baseline a glTF viewer would show. A textured
// cloth's texels multiply each thread's part of the Lambert colour (thread_maps.glsl); a normal
// map tilts the normal as plain normal mapping does (cloth_normal_map.glsl's n′; sheen has no
// threads to turn with it).
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in vec3 v_colour;
in vec2 v_uv;
uniform vec3 u_eye;
out vec4 o_radiance;
void main() {
  vec3 n = normalize(v_normal);
  vec3 wo = normalize(u_eye - v_position);
  if (dot(n, wo) < 0.0) n = -n;
  vec3 u = v_warp;
  if (u_normal_mapped) {
    u = normalize(v_warp - dot(v_warp, n) * n);
    apply_normal_map(n, u, v_uv);
  }
  o_radiance = vec4(sheen_radiance(n, wo, sheen_diffuse(thread_tint(0, v_uv), thread_tint(1, v_uv))), 1.0);
}
