// Method `iwasaki_vertex`: seed 000 evaluated once per mesh vertex (iwasaki.glsl) and the
// radiance interpolated across each triangle (Gouraud). Cheap where pixels far outnumber
// vertices; blurs what varies faster than the mesh (sharp highlights, shadow edges). The
// vertex's own SDF grid, weight 1: a_corners = (i, i, i), a_bary = (1, 0, 0).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_warp;
layout(location = 3) in vec3 a_colour;
layout(location = 4) in vec3 a_corners;
layout(location = 5) in vec3 a_bary;
uniform mat4 u_view_projection;
out vec3 v_radiance;
void main() {
  v_radiance = iwasaki_radiance(a_position, a_normal, a_warp, ivec3(a_corners + 0.5), a_bary);
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
