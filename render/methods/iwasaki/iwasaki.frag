// Method `iwasaki`: iwasaki_radiance per pixel (iwasaki.glsl), the SDF of the triangle's three vertices
// blended by the interpolated one-hot barycentric (seed 000 §3.2 "SDF is interpolated at each pixel"),
// each SG cut by the triangle's own plane as well (facet_horizon_factor), each thread's albedo times
// a texture's texel (thread_maps.glsl), in the frame a normal map turns (cloth_normal_map.glsl).
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in vec2 v_uv;
flat in vec3 v_corners;
in vec3 v_bary;
out vec4 o_radiance;
void main() {
  set_facet_normal(v_position);
  iwasaki_thread_tint[0] = thread_tint(0, v_uv);
  iwasaki_thread_tint[1] = thread_tint(1, v_uv);
  vec3 n = v_normal, u = v_warp;
  iwasaki_behind = dot(v_normal, u_eye - v_position) < 0.0;
  cloth_pixel_frame(v_position, u_eye, v_uv, n, u);
  o_radiance = vec4(iwasaki_radiance(v_position, n, u, ivec3(v_corners + 0.5), v_bary), 1.0);
}
