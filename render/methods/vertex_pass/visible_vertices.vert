// VisibleVertices (methods/vertex_pass/visible_vertices.h): the mesh as the per-vertex rungs' draw
// places it (iwasaki_vertex.vert), invariant so both rasterise the same pixels.
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
invariant gl_Position;
void main() { gl_Position = u_view_projection * vec4(a_position, 1.0); }
