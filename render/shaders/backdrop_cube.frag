// The showroom backdrop from its cube map (gpu/backdrop_cube.h): each pixel's camera ray through
// the inverse view-projection, as background.frag, looked up instead of summed.
uniform mat4 u_inverse_view_projection;
uniform vec2 u_viewport;
uniform samplerCube u_backdrop;
out vec4 o_radiance;
void main() {
  vec2 ndc = gl_FragCoord.xy / u_viewport * 2.0 - 1.0;
  vec4 a = u_inverse_view_projection * vec4(ndc, -1.0, 1.0);
  vec4 b = u_inverse_view_projection * vec4(ndc, 1.0, 1.0);
  o_radiance = vec4(texture(u_backdrop, b.xyz / b.w - a.xyz / a.w).rgb, 1.0);
}
