#pragma once
// Which mesh vertices a frame shows: those of the triangles with a pixel in front. The per-vertex
// passes compute only these (VertexPass::set_marks), so the back of a chair, a cushion's hidden
// faces and what lies off screen cost nothing; the frame stays the one with every vertex computed,
// since the draw interpolates a vertex's values only inside its triangles, and a triangle with no
// pixel in front shows none of them.
// Two draws of every mesh added into a depth target of the frame's size, with one program (so
// both rasterise alike): depth first; then, at depth ≤ the front pulled a little toward the eye
// (a tie or a rounding marks both triangles: more vertices, never fewer), each fragment stores
// the stamp of this view in its triangle's three vertices (shader storage indexed by
// gl_PrimitiveID: GLES 3.2); where the frame already holds the meshes' depth (draw_depth), only the
// second draw, against it. Meshes drawn in front of the cloth by others (the floor) are not
// drawn here: they only hide vertices that are then computed anyway. Where the GL lacks GLES 3.2,
// supported() is false and the passes compute every vertex.
#include <GLES3/gl31.h>

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl_program.h"
#include "gl/gpu_mesh.h"
#include "scene/mesh.h"

namespace weft::gpu {

class VertexPass;

class VisibleVertices {
public:
  static bool supported();  // on the current context
  VisibleVertices();
  VisibleVertices(const VisibleVertices&) = delete;
  ~VisibleVertices();
  // A mesh drawn as `drawn` (the same triangles in the same order); its marks: a uint per vertex,
  // `texels` of them (VertexPass's texel count, the rest never marked). Returns its index.
  size_t add_mesh(const TriangleMesh& mesh, const GpuMesh& drawn, int texels);
  // Marks every mesh's visible vertices under `view_projection` at width × height (the viewport
  // of the frame's draw) unless the last call had the same view; returns the stamp the marks of
  // visible vertices hold. The caller's framebuffer, viewport, program and depth state are kept.
  unsigned mark(const glm::mat4& view_projection, int width, int height);
  // Marks at the bound viewport's size (the frame's, where the draw after the pass rasterises as
  // the marks do) and hands `mesh`'s marks to its `pass` (VertexPass::set_marks).
  void mark_for(VertexPass& pass, size_t mesh, const glm::mat4& view_projection);
  // The mesh's depth alone into the bound framebuffer (colour untouched), as the per-vertex draw
  // places it pushed four depth steps away (ClothMethod::draw_depth); the program in use is kept.
  // Once every mesh's depth is there for a view, mark() for that view in that framebuffer tests
  // against it instead of drawing the meshes' depth again into its own target.
  void draw_depth(size_t mesh, const glm::mat4& view_projection);
  GLuint marks(size_t mesh) const { return meshes_.at(mesh).marks; }
  unsigned stamp() const { return stamp_; }  // the last mark's (0: none yet)
  // How many vertices of `mesh` the last mark found visible (reads the marks back: for tests).
  size_t visible(size_t mesh) const;

private:
  struct Mesh {
    const GpuMesh* drawn;
    GLuint triangles = 0, marks = 0;  // shader storage buffers
    int vertices = 0;
    // The last draw_depth: its view, framebuffer and viewport.
    glm::mat4 depth_view_projection{0.0f};
    GLint depth_framebuffer = -1, depth_viewport[4] = {0, 0, 0, 0};
  };
  GlProgram program_;
  std::vector<Mesh> meshes_;
  GLuint fbo_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
  glm::mat4 view_projection_{0.0f};
  unsigned stamp_ = 0;  // 0: nothing marked yet
};

}  // namespace weft::gpu
