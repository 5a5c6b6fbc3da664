// Linear radiance → display, the operator of render/image/tone_map.h (write_png's too):
// exposure, Hable's filmic curve h(x)/h(W) (its constants WEFT_FILMIC_* are defined from
// tone_map.h's kFilmicCurve when the program is built), sRGB encoding.
uniform highp sampler2D u_linear;
uniform float u_exposure;
out vec4 o_colour;
float hable(float x) {
  const float A = float(WEFT_FILMIC_A), B = float(WEFT_FILMIC_B), C = float(WEFT_FILMIC_C);
  const float D = float(WEFT_FILMIC_D), E = float(WEFT_FILMIC_E), F = float(WEFT_FILMIC_F);
  return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}
float filmic(float x) { return x > 0.0 ? clamp(hable(x) / hable(float(WEFT_FILMIC_W)), 0.0, 1.0) : 0.0; }
float srgb(float x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055; }
void main() {
  vec3 x = u_exposure * max(texelFetch(u_linear, ivec2(gl_FragCoord.xy), 0).rgb, 0.0);
  o_colour = vec4(srgb(filmic(x.r)), srgb(filmic(x.g)), srgb(filmic(x.b)), 1.0);
}
