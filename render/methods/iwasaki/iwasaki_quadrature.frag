// Method `iwasaki_quadrature`: iwasaki per pixel over the SGs it shades (iwasaki.glsl skips the
// broad ones) plus the broad lobes' quadrature from the per-vertex pass (iwasaki_quadrature_pass.frag),
// the triangle's three vertices blended by the interpolated one-hot barycentric.
uniform highp sampler2D u_vertex_radiance;
uniform int u_vertex_width;
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
flat in vec3 v_corners;
in vec3 v_bary;
out vec4 o_radiance;
vec3 vertex_broad(int i) { return texelFetch(u_vertex_radiance, ivec2(i - (i / u_vertex_width) * u_vertex_width, i / u_vertex_width), 0).rgb; }
void main() {
  set_facet_normal(v_position);
  ivec3 c = ivec3(v_corners + 0.5);
  vec3 broad = v_bary.x * vertex_broad(c.x) + v_bary.y * vertex_broad(c.y) + v_bary.z * vertex_broad(c.z);
  o_radiance = vec4(iwasaki_radiance(v_position, v_normal, v_warp, c, v_bary) + broad, 1.0);
}
