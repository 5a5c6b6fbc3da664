#pragma once
// The showroom backdrop (scene_renderer.h's Backdrop::showroom) as a cube map filled when the
// lighting changes: the softened environment is smooth (its sharpest lobe is λ_b = 6), so a small
// cube holds it, and each frame looks it up once per pixel instead of summing every SG there.
#include <glm/glm.hpp>

#include "core/spherical_gaussian.h"
#include "gl/gl_program.h"

namespace weft::gpu {

class BackdropCube {
public:
  // Needs a current GLES 3 context with float render targets; throws GpuError otherwise.
  explicit BackdropCube(int face_size = kFaceSize);
  ~BackdropCube();
  BackdropCube(const BackdropCube&) = delete;
  BackdropCube& operator=(const BackdropCube&) = delete;

  // Σ_k G_k(d) into every face (GL thread); restores the framebuffer and viewport.
  void fill(const SgLighting& sgs);
  // The backdrop behind a camera into the bound framebuffer of width × height; depth state is the
  // caller's (the scene renderer draws it at the far plane behind what it drew).
  void draw(const glm::mat4& inverse_view_projection, int width, int height) const;

  // 32² texels a face: the lookup is within 0.5 % of the SG sum on the softened lobes
  // (backdrop_cube_test measures 0.43 % at worst).
  static constexpr int kFaceSize = 32;

private:
  int size_;
  GLuint texture_ = 0, framebuffer_ = 0;
  GlProgram fill_, draw_;
};

}  // namespace weft::gpu
