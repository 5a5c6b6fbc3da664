// Method `iwasaki`: iwasaki_radiance per pixel (iwasaki.glsl), the SDF of the triangle's three vertices
// blended by the interpolated one-hot barycentric (seed 000 §3.2 "SDF is interpolated at each pixel"),
// and each SG cut by the triangle's own plane as well (facet_horizon_factor).
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
flat in vec3 v_corners;
in vec3 v_bary;
out vec4 o_radiance;
void main() {
  set_facet_normal(v_position);
  o_radiance = vec4(iwasaki_radiance(v_position, v_normal, v_warp, ivec3(v_corners + 0.5), v_bary), 1.0);
}
