// The SG environment seen directly, behind a see-through method's cloth (thin): each pixel's
// camera ray through the inverse view-projection, radiance Σ_k G_k(d). Needs sg_lighting.glsl.
uniform mat4 u_inverse_view_projection;
uniform vec2 u_viewport;
out vec4 o_radiance;
void main() {
  vec2 ndc = gl_FragCoord.xy / u_viewport * 2.0 - 1.0;
  vec4 a = u_inverse_view_projection * vec4(ndc, -1.0, 1.0);
  vec4 b = u_inverse_view_projection * vec4(ndc, 1.0, 1.0);
  vec3 d = normalize(b.xyz / b.w - a.xyz / a.w);
  vec3 l = vec3(0.0);
  for (int k = 0; k < u_sg_count; ++k) l += u_sg_amplitude[k] * exp(u_sg_sharpness[k] * (dot(d, u_sg_axis[k]) - 1.0));
  o_radiance = vec4(l, 1.0);
}
