// Method `thin` (docs/design.md §4): drawn last, blended dst·α + src (GL_ONE, GL_SRC_ALPHA).
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in vec3 v_colour;
uniform vec3 u_eye;
out vec4 o_radiance;
void main() {
  vec3 n = normalize(v_normal);
  vec3 wo = normalize(u_eye - v_position);
  vec3 u = normalize(v_warp - dot(v_warp, n) * n);
  o_radiance = thin_radiance(n, u, wo);
}
