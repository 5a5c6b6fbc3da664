// VisibleVertices (methods/vertex_pass/visible_vertices.h): with u_mark, a fragment in front (the
// depth test runs before the shader) stores u_stamp in its triangle's three vertices; without,
// the depth pass, it only writes depth.
layout(early_fragment_tests) in;
layout(std430, binding = 0) readonly buffer Triangles { uint triangles[]; };  // three vertex indices each
layout(std430, binding = 1) writeonly buffer Marks { uint marks[]; };
uniform bool u_mark;
uniform uint u_stamp;
void main() {
  if (!u_mark) return;
  int t = 3 * gl_PrimitiveID;
  marks[triangles[t]] = u_stamp;
  marks[triangles[t + 1]] = u_stamp;
  marks[triangles[t + 2]] = u_stamp;
}
