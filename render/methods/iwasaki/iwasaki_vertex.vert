// Methods `iwasaki_vertex`, `iwasaki_vertex_mask`, `iwasaki_vertex_quadrature`, step 2: each SG's
// radiance at the mesh vertex, computed by the pass (iwasaki_vertex_pass.frag or
// iwasaki_quadrature_pass.frag: texel (i mod W, i div W + k·rows) for vertex i and SG k), passed on
// per SG so that iwasaki_vertex.frag can cut each by the facet's plane after the rasteriser
// interpolates them (Gouraud). Four SGs per vec4 and colour channel: SG_GROUPS groups (defined by
// the caller, iwasaki_cloth.cpp, from the SGs drawn and the GL's output limit).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_view_projection;
uniform highp sampler2D u_vertex_radiance;
uniform int u_vertex_width;
uniform int u_vertex_rows;
uniform int u_sg_count;
out vec3 v_position;
out vec3 v_normal;
out vec4 v_sg_red[SG_GROUPS];
out vec4 v_sg_green[SG_GROUPS];
out vec4 v_sg_blue[SG_GROUPS];
void main() {
  ivec2 texel = ivec2(gl_VertexID % u_vertex_width, gl_VertexID / u_vertex_width);
  for (int g = 0; g < SG_GROUPS; ++g) {
    vec4 r = vec4(0.0), gr = vec4(0.0), b = vec4(0.0);
    for (int c = 0; c < 4; ++c) {
      int k = 4 * g + c;
      if (k >= u_sg_count) break;
      vec3 x = texelFetch(u_vertex_radiance, texel + ivec2(0, k * u_vertex_rows), 0).rgb;
      r[c] = x.r;
      gr[c] = x.g;
      b[c] = x.b;
    }
    v_sg_red[g] = r;
    v_sg_green[g] = gr;
    v_sg_blue[g] = b;
  }
  v_position = a_position;
  v_normal = a_normal;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
