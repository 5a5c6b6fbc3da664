// Methods `iwasaki_vertex_quadrature` and `iwasaki_quadrature`, the per-vertex pass
// (methods/iwasaki/vertex_pass.h): at every mesh vertex the broad lobes' quadrature
// (broad_lobe_quadrature.glsl), plus, with u_pass_narrow (iwasaki_vertex_quadrature), iwasaki over
// the other SGs with the vertex's own SDF values; iwasaki_quadrature shades those per pixel.
uniform highp sampler2D u_vertex_position;
uniform highp sampler2D u_vertex_normal;
uniform highp sampler2D u_vertex_warp;
uniform int u_vertex_width;
uniform int u_vertex_count;
uniform bool u_pass_narrow;
out vec4 o_radiance;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int i = p.y * u_vertex_width + p.x;
  if (i >= u_vertex_count) {
    o_radiance = vec4(0.0);
    return;
  }
  vec3 position = texelFetch(u_vertex_position, p, 0).xyz, normal = texelFetch(u_vertex_normal, p, 0).xyz,
       warp = texelFetch(u_vertex_warp, p, 0).xyz;
  vec3 radiance = broad_lobe_radiance(i, position, normal, warp);
  if (u_pass_narrow) radiance += iwasaki_radiance(position, normal, warp, ivec3(i), vec3(1.0, 0.0, 0.0));
  o_radiance = vec4(radiance, 1.0);
}
