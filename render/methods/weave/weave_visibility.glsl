// Each vertex's share of every weave light that the object's geometry leaves open
// (methods/weave/weave_lights.h's weave_light_visibility), four lights to an RGBA32F texel:
// vertex v's group g at (v mod W, v div W + g·rows). Without it (u_weave_visibility false: an
// unoccluded object) every share is 1.
uniform bool u_weave_visibility;
uniform highp sampler2D u_weave_visibility_texels;
uniform int u_weave_visibility_width;
uniform int u_weave_visibility_rows;
vec4 weave_visibility(int vertex, int group) {
  if (!u_weave_visibility) return vec4(1.0);
  int w = u_weave_visibility_width;
  return texelFetch(u_weave_visibility_texels, ivec2(vertex % w, vertex / w + group * u_weave_visibility_rows), 0);
}
