// A textured cloth's thread maps (scene/scene.h's ThreadMap, methods/thread_map_textures.h): each
// thread's albedo times the texel at the point's UV, read through the map's KHR_texture_transform
// (a mat3 on (u, v, 1)). The textures are sRGB, so the sampler returns linear RGB, mip-mapped.
// Untextured: 1 (the samplers then hold a white texel).
uniform bool u_textured;
uniform mediump sampler2D u_warp_map;
uniform mediump sampler2D u_weft_map;
uniform mat3 u_warp_uv;
uniform mat3 u_weft_uv;
vec3 thread_tint(int thread, vec2 uv) {
  if (!u_textured) return vec3(1.0);
  if (thread == 0) return texture(u_warp_map, (u_warp_uv * vec3(uv, 1.0)).xy).rgb;
  return texture(u_weft_map, (u_weft_uv * vec3(uv, 1.0)).xy).rgb;
}
