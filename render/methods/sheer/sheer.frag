// Method `sheer`: the thin layer over iwasaki per pixel (sheer.glsl), the SDF of the
// triangle's three vertices blended as iwasaki.frag does; premultiplied source and alpha, blended
// over what lies behind as dst·α + src.
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
flat in vec3 v_corners;
in vec3 v_bary;
out vec4 o_radiance;
void main() {
  sheer_position = v_position;
  sheer_mesh_normal = v_normal;
  sheer_warp = v_warp;
  sheer_corners = ivec3(v_corners + 0.5);
  sheer_bary = v_bary;
  vec3 n = normalize(v_normal);
  o_radiance = thin_radiance(n, normalize(v_warp - dot(v_warp, n) * n), normalize(u_eye - v_position));
}
