// The kiosk's label (render/label/label_overlay.h): white text over a dark translucent plate,
// premultiplied, for blending with (ONE, ONE_MINUS_SRC_ALPHA) over the tone-mapped frame. The
// coverage image is fetched texel for pixel (no filtering): the text stays as FreeType drew it.
uniform mediump sampler2D u_coverage;
uniform ivec2 u_origin;   // the box's lower-left pixel in the framebuffer
uniform int u_height;     // the image's rows (its row 0 is the box's top)
uniform float u_plate;    // the plate's alpha where there is no text
uniform float u_opacity;  // the fade: 0 … 1
out vec4 o_colour;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy) - u_origin;
  float c = texelFetch(u_coverage, ivec2(p.x, u_height - 1 - p.y), 0).r;
  o_colour = vec4(vec3(c), c + u_plate * (1.0 - c)) * u_opacity;
}
