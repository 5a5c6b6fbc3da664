// A cloth's normal map (scene/scene.h's NormalMap) at the pixel: the texel read linearly (the
// texture is RGBA8, not sRGB) through the map's transform, mip-mapped, then renormalized and
// applied by normal_map_frame.glsl. Without one the frame is left as it is.
uniform bool u_normal_mapped;
uniform mediump sampler2D u_normal_map;
uniform mat3 u_normal_uv;
uniform float u_normal_scale;
// The map's unit tangent-space normal at uv; (0, 0, 1) without a map.
vec3 normal_map_at(vec2 uv) {
  if (!u_normal_mapped) return vec3(0.0, 0.0, 1.0);
  vec3 texel = texture(u_normal_map, (u_normal_uv * vec3(uv, 1.0)).xy).rgb;
  return tangent_space_normal(texel, u_normal_scale);
}
void apply_normal_map(inout vec3 n, inout vec3 u, vec2 uv) {
  if (!u_normal_mapped) return;
  normal_mapped_frame(n, u, normal_map_at(uv));
}
// The shading frame at a cloth pixel: the interpolated normal on the side facing the eye, the
// warp made orthogonal to it, both turned by the normal map.
void cloth_pixel_frame(vec3 position, vec3 eye, vec2 uv, inout vec3 n, inout vec3 u) {
  n = normalize(n);
  if (dot(n, eye - position) < 0.0) n = -n;
  u = normalize(u - dot(u, n) * n);
  apply_normal_map(n, u, uv);
}
