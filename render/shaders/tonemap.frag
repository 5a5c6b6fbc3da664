// Linear radiance → display, the same operator as render/image's write_png: the soft
// shoulder 1 − e^{−exposure·radiance} per channel, then sRGB encoding.
uniform highp sampler2D u_linear;
uniform float u_exposure;
out vec4 o_colour;
float srgb(float x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055; }
void main() {
  vec3 c = 1.0 - exp(-u_exposure * max(texelFetch(u_linear, ivec2(gl_FragCoord.xy), 0).rgb, 0.0));
  o_colour = vec4(srgb(c.r), srgb(c.g), srgb(c.b), 1.0);
}
