// Method `sheen` (docs/design.md §4): the peer baseline a glTF viewer would show.
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
  o_radiance = vec4(sheen_radiance(n, wo), 1.0);
}
