// Method `iwasaki_quadrature`: iwasaki per pixel over the SGs it shades (iwasaki.glsl skips the
// broad ones) plus the broad lobes' quadrature from the per-vertex pass (iwasaki_quadrature_pass.frag:
// three blocks, the surface part and each thread's volume part per unit albedo), the triangle's
// three vertices blended by the interpolated one-hot barycentric, the albedos (times a texture's
// texels, thread_maps.glsl) applied here. A normal map turns the sharp lobes' frame per pixel
// (cloth_normal_map.glsl); the broad lobes, smooth in the normal, keep the vertices' normals.
uniform highp sampler2D u_vertex_radiance;
uniform int u_vertex_width;
uniform int u_vertex_rows;
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in vec2 v_uv;
flat in vec3 v_corners;
in vec3 v_bary;
out vec4 o_radiance;
vec3 vertex_broad(int i, int block) {
  return texelFetch(u_vertex_radiance, ivec2(i - (i / u_vertex_width) * u_vertex_width, i / u_vertex_width + block * u_vertex_rows), 0).rgb;
}
vec3 blended_broad(ivec3 c, int block) {
  return v_bary.x * vertex_broad(c.x, block) + v_bary.y * vertex_broad(c.y, block) + v_bary.z * vertex_broad(c.z, block);
}
void main() {
  set_facet_normal(v_position);
  iwasaki_thread_tint[0] = thread_tint(0, v_uv);
  iwasaki_thread_tint[1] = thread_tint(1, v_uv);
  vec3 n = v_normal, u = v_warp;
  iwasaki_behind = dot(v_normal, u_eye - v_position) < 0.0;
  cloth_pixel_frame(v_position, u_eye, v_uv, n, u);
  ivec3 c = ivec3(v_corners + 0.5);
  vec3 broad = blended_broad(c, 0) + u_threads[0].albedo * iwasaki_thread_tint[0] * blended_broad(c, 1) +
               u_threads[1].albedo * iwasaki_thread_tint[1] * blended_broad(c, 2);
  o_radiance = vec4(iwasaki_radiance(v_position, n, u, c, v_bary) + broad, 1.0);
}
