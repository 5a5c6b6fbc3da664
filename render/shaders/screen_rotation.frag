// The upright picture (u_picture) turned clockwise by u_quarter_turns quarter turns onto the
// screen, pixel for pixel (texelFetch: no filtering). The turn is worked out in image
// coordinates, row 0 at the top; GL's rows count from the bottom, hence the flips in and out.
uniform mediump sampler2D u_picture;
uniform int u_quarter_turns;
out vec4 o_colour;
void main() {
  ivec2 size = textureSize(u_picture, 0);  // the picture's width and height
  bool quarter = u_quarter_turns == 1 || u_quarter_turns == 3;
  int screen_h = quarter ? size.x : size.y;
  ivec2 s = ivec2(gl_FragCoord.xy);
  s.y = screen_h - 1 - s.y;  // the screen pixel, from the top
  ivec2 p = s;               // the picture's pixel shown there, from the top
  if (u_quarter_turns == 1) p = ivec2(s.y, size.y - 1 - s.x);
  else if (u_quarter_turns == 2) p = ivec2(size.x - 1 - s.x, size.y - 1 - s.y);
  else if (u_quarter_turns == 3) p = ivec2(size.x - 1 - s.y, s.x);
  o_colour = texelFetch(u_picture, ivec2(p.x, size.y - 1 - p.y), 0);
}
