// Method `mdfrot` (docs/design.md §4).
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in vec3 v_colour;
uniform vec3 u_eye;
out vec4 o_radiance;
void main() {
  vec3 n = normalize(v_normal);
  vec3 wo = normalize(u_eye - v_position);
  if (dot(n, wo) < 0.0) n = -n;
  vec3 u = normalize(v_warp - dot(v_warp, n) * n);
  o_radiance = vec4(mdfrot_radiance(n, u, wo), 1.0);
}
