// Methods `iwasaki_vertex`, `iwasaki_vertex_mask`, `iwasaki_vertex_quadrature`, step 2: each SG's
// light at the mesh vertex at unit amplitude, split as (surface, warp volume, weft volume) by the
// pass (iwasaki_vertex_pass.frag or iwasaki_quadrature_pass.frag: texel (i mod W, i div W + k·rows)
// for vertex i and SG k), passed on per SG so that iwasaki_vertex.frag can apply the amplitudes,
// the albedos with a texture's texels, and cut each SG by the facet's plane after the rasteriser
// interpolates them (Gouraud: the parts are linear in the albedo, so interpolating them first is
// exact); the warp with them, for the frame a normal map turns. With the pass's history, each kept
// value carried on to the frame's time (vertex_history.glsl, before this file). Four SGs per vec4
// and part: SG_GROUPS groups (defined by the caller, iwasaki_cloth.cpp, from the SGs drawn and the
// GL's output limit).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_warp;
layout(location = 6) in vec3 a_uv;
uniform mat4 u_view_projection;
uniform highp sampler2D u_vertex_radiance;
uniform int u_vertex_width;
uniform int u_vertex_rows;
uniform int u_sg_count;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_warp;
out vec2 v_uv;
out vec4 v_sg_surface[SG_GROUPS];
out vec4 v_sg_warp[SG_GROUPS];
out vec4 v_sg_weft[SG_GROUPS];
invariant gl_Position;  // as visible_vertices.vert's, which marks the vertices this draw shows
void main() {
  ivec2 texel = ivec2(gl_VertexID % u_vertex_width, gl_VertexID / u_vertex_width);
  for (int g = 0; g < SG_GROUPS; ++g) {
    vec4 s = vec4(0.0), w = vec4(0.0), f = vec4(0.0);
    for (int c = 0; c < 4; ++c) {
      int k = 4 * g + c;
      if (k >= u_sg_count) break;
      ivec2 at = texel + ivec2(0, k * u_vertex_rows);
      vec3 x = extrapolated_value(texelFetch(u_vertex_radiance, at, 0), at, k);
      s[c] = x.x;
      w[c] = x.y;
      f[c] = x.z;
    }
    v_sg_surface[g] = s;
    v_sg_warp[g] = w;
    v_sg_weft[g] = f;
  }
  v_position = a_position;
  v_normal = a_normal;
  v_warp = a_warp;
  v_uv = a_uv.xy;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
